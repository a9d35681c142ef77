// The preview's fixed per-pixel offsets (sampling/dither.h): in [0, 1), the same for a pixel every
// time, spread evenly over [0, 1) across an image (so that a march's samples cover each step evenly
// across neighbouring pixels), and different between neighbours (so that a step's phase does not
// draw rings across them).
#include "sampling/dither.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vs::shared;

TEST(Dither, InterleavedGradientNoise)
{
  const uint32_t n = 256, bins = 16;
  double counts[bins] = {};
  double neighbourGap = 0.0;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x)
    {
      const float v = vs_interleaved_gradient_noise(uvec2(x, y));
      ASSERT_GE(v, 0.0f);
      ASSERT_LT(v, 1.0f);
      EXPECT_EQ(v, vs_interleaved_gradient_noise(uvec2(x, y)));
      counts[std::min(uint32_t(v * bins), bins - 1)] += 1.0;
      neighbourGap += std::abs(v - vs_interleaved_gradient_noise(uvec2(x + 1, y))) +
        std::abs(v - vs_interleaved_gradient_noise(uvec2(x, y + 1)));
    }
  // Even: chi-square of the 16 bins' counts against uniform (15 degrees of freedom; 37.7 is its 0.001
  // quantile).
  const double expected = double(n) * n / bins;
  double chi2 = 0.0;
  for (double c : counts)
    chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, 37.7);
  // Neighbours far apart: for independent uniform values the mean gap would be 1/3.
  EXPECT_GT(neighbourGap / (2.0 * n * n), 0.3);
}
