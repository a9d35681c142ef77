// The series of Kettunen et al. 2021's unbiased ray-marching transmittance estimator
// (sampling/ray_marching.h): the roulette's order probabilities and their expected order (the paper's
// 0.31945), the march's sample count, and the estimator itself on the CPU, built from the same
// functions as the shader's march_transmittance: its mean is exp(-tau) within the standard error on
// a medium whose ray march is far off (where exp(-march), plain ray marching, is visibly biased).
#include "sampling/ray_marching.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace vs::shared;

TEST(RayMarchingSeries, OrderProbabilities)
{
  EXPECT_FLOAT_EQ(vs_rm_order_probability(0), 1.0f);
  EXPECT_FLOAT_EQ(vs_rm_order_probability(1), 1.0f - VS_RM_ORDER_ZERO);
  EXPECT_FLOAT_EQ(vs_rm_order_probability(2), 1.0f - VS_RM_ORDER_ZERO); // at least K = 2 terms
  EXPECT_FLOAT_EQ(vs_rm_order_probability(3), (1.0f - VS_RM_ORDER_ZERO) * 2.0f / 3.0f);
  double expected = 0.0; // E[N] = sum_{k >= 1} P(N >= k)
  for (uint32_t k = 1; k < 40; ++k)
  {
    EXPECT_GT(vs_rm_order_probability(k), 0.0f) << k; // every order possible: no truncation
    EXPECT_LE(vs_rm_continue_probability(k), 1.0f) << k;
    expected += vs_rm_order_probability(k);
  }
  EXPECT_NEAR(expected, 0.31945, 1e-4); // the expected number of further marches in the paper
  // The running product: prod_{i<=k} (x0 - xi) / (k! P(N >= k)).
  float term = 1.0f;
  double factorial = 1.0;
  for (uint32_t k = 1; k <= 6; ++k)
  {
    term *= vs_rm_term_factor(3.0f, 1.5f, k);
    factorial *= k;
    EXPECT_NEAR(term, std::pow(1.5, k) / (factorial * vs_rm_order_probability(k)), 1e-4 * term) << k;
  }
}

TEST(RayMarchingSeries, SampleCount)
{
  EXPECT_EQ(vs_rm_sample_count(0.0f), 1.0f);
  EXPECT_EQ(vs_rm_sample_count(-1.0f), 1.0f);
  EXPECT_EQ(vs_rm_sample_count(1.0f), 4.0f); // ceil(cbrt(1.015 * 1.65 * 61.3)) = 5, / 1.31945
  float last = 1.0f;
  for (float tau = 0.0f; tau < 1000.0f; tau = tau * 1.3f + 0.01f)
  {
    float n = vs_rm_sample_count(tau);
    EXPECT_GE(n, last) << tau;
    EXPECT_EQ(n, std::floor(n)) << tau;
    EXPECT_LE(n, VS_RM_MAX_SAMPLES) << tau;
    last = n;
  }
  EXPECT_EQ(vs_rm_sample_count(1e30f), VS_RM_MAX_SAMPLES);
}

namespace
{
// A 1D medium on [0, 1]: a slab of extinction 12 on [0.3, 0.55] over a background of 0.5 (tau = 3.375),
// marched with the shader's uniform jitter at M samples: very noisy at this M.
double Extinction(double t)
{
  return (t >= 0.3 && t < 0.55) ? 12.0 : 0.5;
}
const double kTau = 0.25 * 12.0 + 0.75 * 0.5;

double March(std::mt19937_64& rng, int M)
{
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double u = u01(rng), h = 1.0 / M;
  double x = 0.0;
  for (int j = 0; j < M; ++j)
    x += Extinction((u + j) * h) * h;
  return x;
}

// march_transmittance's series on the CPU.
double Series(std::mt19937_64& rng, int M, bool correct)
{
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  const double x0 = March(rng, M);
  double sum = 1.0, term = 1.0;
  for (uint32_t k = 1; correct; ++k)
  {
    if (u01(rng) >= vs_rm_continue_probability(k))
      break;
    term *= vs_rm_term_factor(float(x0), float(March(rng, M)), k);
    sum += term;
  }
  return std::exp(-x0) * sum;
}
}

TEST(RayMarchingSeries, UnbiasedWhereRayMarchingIsNot)
{
  for (int M : { 3, 5, 7 })
  {
    std::mt19937_64 rng(1234 + M);
    for (bool correct : { true, false })
    {
      const int n = 400000;
      double s = 0.0, s2 = 0.0;
      for (int i = 0; i < n; ++i)
      {
        double T = Series(rng, M, correct);
        s += T;
        s2 += T * T;
      }
      const double mean = s / n, se = std::sqrt((s2 / n - mean * mean) / n);
      const double z = (mean - std::exp(-kTau)) / se;
      std::printf("[ ray marching ] M %d %s: mean %.5f (exp(-tau) %.5f), z %.2f, variance %.4g\n", M,
        correct ? "series" : "exp(-march)", mean, std::exp(-kTau), z, s2 / n - mean * mean);
      if (correct)
        EXPECT_LT(std::abs(z), 4.5) << M;
      else
        EXPECT_GT(z, 10.0) << M << ": plain ray marching is biased upwards here (Jensen)";
    }
  }
}
