// The display transform (sampling/display_transform.h), which the host's window image of the Monte
// Carlo estimate and the device's of the preview both take: its values at known points, and the
// window pixel's defining properties. Composited over the skybox (which shows the environment's
// display colour B), the pixel C drawn with coverage a, C + (1 - a) B, is the opaque image's F(L);
// painting, the premultiplied pixel is a F(L / a) with the alpha asked for.
#include "sampling/display_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace vs::shared;

TEST(DisplayTransform, KnownValues)
{
  EXPECT_EQ(vs_display_value(0.0f, false), 0.0f);
  EXPECT_EQ(vs_display_value(0.0f, true), 0.0f);
  EXPECT_FLOAT_EQ(vs_display_value(1.0f, false), 1.0f);
  EXPECT_FLOAT_EQ(vs_display_value(7.0f, false), 1.0f); // the clamp
  EXPECT_NEAR(vs_display_value(0.5f, false), 0.735357f, 1e-6f); // sRGB of 0.5
  EXPECT_NEAR(vs_display_value(0.002f, false), 12.92f * 0.002f, 1e-7f); // its linear toe
  EXPECT_LT(vs_display_value(1.0f, true), 1.0f);          // the filmic curve's shoulder
  // Narkowicz's fit reaches 1 at l = 7.24 (0.08 l^2 - 0.56 l - 0.14 = 0), then clamps.
  EXPECT_LT(vs_display_value(7.0f, true), 1.0f);
  EXPECT_FLOAT_EQ(vs_display_value(7.5f, true), 1.0f); // sRGB's 1.055 - 0.055 is 1 within an ulp
  float last = 0.0f;
  for (float l = 1e-4f; l < 7.0f; l *= 1.1f)
  {
    EXPECT_GT(vs_display_value(l, true), last) << l; // increasing below
    last = vs_display_value(l, true);
  }
  const vec3 rgb = vs_display_rgb(vec3(0.5f, 0.0f, 2.0f), false);
  EXPECT_EQ(rgb.x, vs_display_value(0.5f, false));
  EXPECT_EQ(rgb.y, 0.0f);
  EXPECT_EQ(rgb.z, vs_display_value(2.0f, false));
}

TEST(DisplayTransform, WindowPixel)
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i)
  {
    const bool toneMapping = i % 2 == 0;
    const float exposure = 0.25f + 2.0f * u(gen);
    const float a = u(gen);
    const vec3 environment(3.0f * u(gen), 3.0f * u(gen), 3.0f * u(gen));
    // Radiance seen through a medium of coverage a: its own light plus T x the environment.
    const vec4 radiance(vec3(u(gen), u(gen), u(gen)) * a + (1.0f - a) * environment, a);
    const vec3 background = vs_display_rgb(exposure * environment, toneMapping);
    const vec4 over = vs_display_pixel(radiance, true, true, background, 1.0f, exposure, toneMapping);
    const vec3 full = vs_display_rgb(exposure * vec3(radiance), toneMapping);
    EXPECT_FLOAT_EQ(over.w, a);
    for (int k = 0; k < 3; ++k)
    {
      if (over[k] > 0.0f) // clamped at 0 only where F(L) < (1 - a) B
        EXPECT_NEAR(over[k] + (1.0f - a) * background[k], full[k], 1e-6f) << i;
      else
        EXPECT_LE(full[k], (1.0f - a) * background[k] + 1e-6f) << i;
    }
    // Painting the environment: opaque, the full radiance.
    const vec4 painted = vs_display_pixel(radiance, true, false, background, 1.0f, exposure, toneMapping);
    EXPECT_EQ(painted, vec4(full, 1.0f));
    // Not seeing the environment: premultiplied by the coverage.
    const vec4 alone = vs_display_pixel(radiance, false, true, background, 1.0f, exposure, toneMapping);
    EXPECT_FLOAT_EQ(alone.w, a);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(alone[k], a * vs_display_value(exposure * radiance[k] / a, toneMapping), 1e-6f) << i;
  }
  // Nothing met (a = 0): transparent, over the background or alone.
  EXPECT_EQ(vs_display_pixel(vec4(0.3f, 0.2f, 0.1f, 0.0f), true, true, vec3(0.5f), 1.0f, 1.0f, true), vec4(0.0f));
  EXPECT_EQ(vs_display_pixel(vec4(0.0f), false, false, vec3(0.5f), 1.0f, 1.0f, true), vec4(0.0f));
}
