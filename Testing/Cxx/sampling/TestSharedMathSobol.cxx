// The pixels' scrambled Sobol sequences (sampling/sobol.h): the loop-free second dimension equals the
// textbook generator, every prefix of 2^m points of every seed is a (0,m,2)-net (one point in every
// elementary box), a single point is uniform over seeds (chi-square: the estimator stays unbiased),
// and two seeds' sequences are not correlated.
#include "sampling/sobol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vs::shared;

namespace
{
double ChiSquareQuantile999(double dof)
{
  const double z = 3.090232;
  double t = 1.0 - 2.0 / (9.0 * dof) + z * std::sqrt(2.0 / (9.0 * dof));
  return dof * t * t * t;
}
}

TEST(Sobol, SecondDimensionIsPascalsMatrix)
{
  for (uint32_t i = 0; i < (1u << 16); ++i)
  {
    ASSERT_EQ(vs_sobol_dimension1(i), vs_sobol_dimension1_reference(i)) << i;
  }
  for (uint32_t i : { 0xFFFFFFFFu, 0x80000000u, 0x12345678u, 0xDEADBEEFu })
  {
    EXPECT_EQ(vs_sobol_dimension1(i), vs_sobol_dimension1_reference(i)) << i;
  }
}

TEST(Sobol, EveryPrefixIsANet)
{
  for (uint32_t seed : { 0u, 1u, 77u, 0xCAFEF00Du })
  {
    for (int m = 1; m <= 10; ++m)
    {
      const uint32_t n = 1u << m;
      std::vector<vec2> p(n);
      for (uint32_t i = 0; i < n; ++i)
      {
        p[i] = vs_sobol_2d(i, seed);
        ASSERT_GE(p[i].x, 0.0f);
        ASSERT_LT(p[i].x, 1.0f);
        ASSERT_GE(p[i].y, 0.0f);
        ASSERT_LT(p[i].y, 1.0f);
      }
      // Every shape of elementary box: 2^a columns by 2^(m-a) rows, one point each.
      for (int a = 0; a <= m; ++a)
      {
        const uint32_t cols = 1u << a, rows = 1u << (m - a);
        std::vector<int> count(n, 0);
        for (const vec2& q : p)
        {
          count[uint32_t(q.y * float(rows)) * cols + uint32_t(q.x * float(cols))]++;
        }
        for (uint32_t b = 0; b < n; ++b)
        {
          ASSERT_EQ(count[b], 1) << "seed " << seed << ", 2^" << m << " points, box " << b << " of " << cols
                                 << " x " << rows;
        }
      }
    }
  }
}

TEST(Sobol, EachPointIsUniformOverSeeds)
{
  const int bins = 16, seeds = 1 << 16;
  for (uint32_t index : { 0u, 1u, 5u, 1000u })
  {
    std::vector<double> hist(bins * bins, 0.0);
    for (int s = 0; s < seeds; ++s)
    {
      vec2 u = vs_sobol_2d(index, vs_hash_seed(uint32_t(s), 12345u));
      hist[std::min(bins - 1, int(u.y * bins)) * bins + std::min(bins - 1, int(u.x * bins))] += 1.0;
    }
    const double expected = double(seeds) / (bins * bins);
    double chi2 = 0.0;
    for (double h : hist)
    {
      chi2 += (h - expected) * (h - expected) / expected;
    }
    EXPECT_LT(chi2, ChiSquareQuantile999(bins * bins - 1)) << "point " << index;
  }
}

TEST(Sobol, TwoSeedsAreUncorrelated)
{
  // The jitter and the light direction of a pixel's samples use two seeds: the products of their
  // coordinates over 4096 points average 1/4 (independent uniforms) within 4 standard errors.
  const uint32_t n = 4096;
  for (uint32_t pixel = 0; pixel < 8; ++pixel)
  {
    const uint32_t a = vs_hash_seed(pixel, 1u), b = vs_hash_seed(pixel, 2u);
    double xx = 0.0, yy = 0.0;
    for (uint32_t i = 0; i < n; ++i)
    {
      vec2 p = vs_sobol_2d(i, a), q = vs_sobol_2d(i, b);
      xx += double(p.x) * q.x;
      yy += double(p.y) * q.y;
    }
    const double sd = std::sqrt(7.0 / 144.0 / n); // var(XY) = 1/9 - 1/16 for independent uniforms
    EXPECT_NEAR(xx / n, 0.25, 4.0 * sd) << pixel;
    EXPECT_NEAR(yy / n, 0.25, 4.0 * sd) << pixel;
  }
}
