// The equal-area octahedral map, exactly as the shaders compile it.
#include "shared/octahedral.h"
#include "shared/rng.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vs::shared;

TEST(Octahedral, RoundTripDirectionUvDirection)
{
  VsRng rng = vs_rng_init(uvec2(7u, 3u), 0u, 42u);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i)
  {
    // A uniform direction on the sphere.
    vec2 u = vs_rng_vec2(rng);
    float z = 1.0f - 2.0f * u.x;
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * VS_PI * u.y;
    vec3 d(r * std::cos(phi), r * std::sin(phi), z);
    vec3 e = vs_octa_to_dir(vs_dir_to_octa(d));
    worst = std::max(worst, double(glm::length(e - d)));
  }
  EXPECT_LT(worst, 1e-5);
}

TEST(Octahedral, AxesAndSeams)
{
  const vec3 axes[] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
    glm::normalize(vec3(1, 1, 0)), glm::normalize(vec3(-1, 1, -1)), glm::normalize(vec3(1, -1, 1)) };
  for (vec3 d : axes)
  {
    vec2 uv = vs_dir_to_octa(d);
    EXPECT_GE(uv.x, 0.0f);
    EXPECT_LE(uv.x, 1.0f);
    EXPECT_GE(uv.y, 0.0f);
    EXPECT_LE(uv.y, 1.0f);
    EXPECT_LT(glm::length(vs_octa_to_dir(uv) - d), 1e-5f) << d.x << " " << d.y << " " << d.z;
  }
  EXPECT_NEAR(vs_octa_to_dir(vec2(0.5f)).z, 1.0f, 1e-6f);
  EXPECT_NEAR(vs_octa_to_dir(vec2(0.0f)).z, -1.0f, 1e-6f);
}

// Solid angle of a spherical triangle (Van Oosterom and Strackee).
static double TriangleSolidAngle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c)
{
  double num = glm::dot(a, glm::cross(b, c));
  double den = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
  return std::abs(2.0 * std::atan2(num, den));
}

// Every texel of a 2^k x 2^k map covers 4*pi/4^k: integrate each texel's image on
// the sphere by subdividing it into small spherical quads (two triangles each).
TEST(Octahedral, EqualAreaTexels)
{
  for (int k = 1; k <= 5; ++k)
  {
    const int n = 1 << k;
    const int sub = 64 >> (k - 1) < 16 ? 16 : 64 >> (k - 1);
    const double expected = 4.0 * M_PI / (n * n);
    double worst = 0.0, total = 0.0;
    for (int ty = 0; ty < n; ++ty)
    {
      for (int tx = 0; tx < n; ++tx)
      {
        double area = 0.0;
        for (int j = 0; j < sub; ++j)
        {
          for (int i = 0; i < sub; ++i)
          {
            auto P = [&](int a, int b) {
              double u = (tx + double(i + a) / sub) / n;
              double v = (ty + double(j + b) / sub) / n;
              return glm::normalize(glm::dvec3(vs_octa_to_dir(vec2(float(u), float(v)))));
            };
            glm::dvec3 p00 = P(0, 0), p10 = P(1, 0), p01 = P(0, 1), p11 = P(1, 1);
            area += TriangleSolidAngle(p00, p10, p11) + TriangleSolidAngle(p00, p11, p01);
          }
        }
        total += area;
        worst = std::max(worst, std::abs(area / expected - 1.0));
      }
    }
    EXPECT_LT(worst, 1e-3) << "k = " << k;
    EXPECT_NEAR(total, 4.0 * M_PI, 1e-3) << "k = " << k;
  }
}

TEST(Octahedral, TexelLookupMatchesCentre)
{
  for (uint n : { 4u, 8u, 16u })
  {
    for (uint y = 0; y < n; ++y)
    {
      for (uint x = 0; x < n; ++x)
      {
        uvec2 t = vs_dir_to_texel(vs_texel_dir(uvec2(x, y), n), n);
        EXPECT_EQ(t.x, x);
        EXPECT_EQ(t.y, y);
      }
    }
  }
}
