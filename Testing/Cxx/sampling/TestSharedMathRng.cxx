// The counter-based RNG the shaders use: uniformity (chi-square), independence
// of neighbouring pixels and dimensions, and reproducibility.
#include "sampling/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vs::shared;

// Upper 0.999 quantile of chi-square with `dof` degrees of freedom (Wilson-Hilferty).
static double ChiSquareQuantile999(double dof)
{
  const double z = 3.090232;
  double t = 1.0 - 2.0 / (9.0 * dof) + z * std::sqrt(2.0 / (9.0 * dof));
  return dof * t * t * t;
}

TEST(Rng, UniformWithinOnePixel)
{
  const int bins = 256, samples = 1 << 20;
  std::vector<double> hist(bins, 0.0);
  VsRng r = vs_rng_init(uvec2(12u, 34u), 5u, 1u);
  for (int i = 0; i < samples; ++i)
  {
    float u = vs_rng_float(r);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    hist[std::min(bins - 1, int(u * bins))] += 1.0;
  }
  double expected = double(samples) / bins, chi2 = 0.0;
  for (double h : hist)
  {
    chi2 += (h - expected) * (h - expected) / expected;
  }
  EXPECT_LT(chi2, ChiSquareQuantile999(bins - 1));
}

TEST(Rng, UniformAcrossPixelsAndFrames2D)
{
  // First sample of many pixels and frames: the hash must decorrelate neighbours.
  const int side = 32, bins = side * side;
  std::vector<double> hist(bins, 0.0);
  int samples = 0;
  for (uint frame = 0; frame < 4; ++frame)
  {
    for (uint y = 0; y < 256; ++y)
    {
      for (uint x = 0; x < 256; ++x)
      {
        VsRng r = vs_rng_init(uvec2(x, y), frame, 7u);
        vec2 u = vs_rng_vec2(r);
        hist[int(u.y * side) * side + int(u.x * side)] += 1.0;
        ++samples;
      }
    }
  }
  double expected = double(samples) / bins, chi2 = 0.0;
  for (double h : hist)
  {
    chi2 += (h - expected) * (h - expected) / expected;
  }
  EXPECT_LT(chi2, ChiSquareQuantile999(bins - 1));
}

TEST(Rng, ReproducibleAndSeedDependent)
{
  VsRng a = vs_rng_init(uvec2(1u, 2u), 3u, 4u);
  VsRng b = vs_rng_init(uvec2(1u, 2u), 3u, 4u);
  VsRng c = vs_rng_init(uvec2(1u, 2u), 3u, 5u);
  int same = 0;
  for (int i = 0; i < 100; ++i)
  {
    uint x = vs_rng_uint(a);
    EXPECT_EQ(x, vs_rng_uint(b));
    same += x == vs_rng_uint(c);
  }
  EXPECT_LT(same, 3);
}
