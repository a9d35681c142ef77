// mis.h on the CPU: the heuristics' weights of two strategies sum to 1 for every pair of pdfs (the
// condition for an unbiased combination), the power heuristic's known values and limits, and
// Russian roulette's survival probability (1 before its depth, capped at 0.95, 0 for a dead path).
#include "sampling/mis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace vs::shared;

TEST(SharedMathMis, WeightsSumToOne)
{
  const float pdfs[] = { 1e-30f, 1e-6f, 0.01f, 0.0795775f, 1.0f, 37.0f, 1e6f, 1e30f };
  for (float nl : { 1.0f, 4.0f, 64.0f })
  {
    for (float pl : pdfs)
    {
      for (float pp : pdfs)
      {
        const float power = vs_power_heuristic(nl, pl, 1.0f, pp) + vs_power_heuristic(1.0f, pp, nl, pl);
        const float balance = vs_balance_heuristic(nl, pl, 1.0f, pp) + vs_balance_heuristic(1.0f, pp, nl, pl);
        EXPECT_NEAR(power, 1.0f, 1e-6f) << nl << " " << pl << " " << pp;
        EXPECT_NEAR(balance, 1.0f, 1e-6f) << nl << " " << pl << " " << pp;
      }
    }
  }
}

TEST(SharedMathMis, KnownValues)
{
  EXPECT_FLOAT_EQ(vs_power_heuristic(1.0f, 2.0f, 1.0f, 1.0f), 0.8f);   // 4 / (4 + 1)
  EXPECT_FLOAT_EQ(vs_balance_heuristic(1.0f, 2.0f, 1.0f, 1.0f), 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(vs_power_heuristic(2.0f, 1.0f, 1.0f, 1.0f), 0.8f);   // two samples count twice
  // A strategy that cannot produce the direction gives the other everything.
  EXPECT_EQ(vs_power_heuristic(1.0f, 0.0f, 1.0f, 1.0f), 0.0f);
  EXPECT_EQ(vs_power_heuristic(1.0f, 1.0f, 1.0f, 0.0f), 1.0f);
  EXPECT_EQ(vs_power_heuristic(1.0f, std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f), 0.0f);
}

TEST(SharedMathMis, RouletteSurvival)
{
  EXPECT_EQ(vs_roulette_survival(vec3(0.1f), 2u, 4u), 1.0f);
  EXPECT_FLOAT_EQ(vs_roulette_survival(vec3(0.1f, 0.3f, 0.2f), 4u, 4u), 0.3f);
  EXPECT_FLOAT_EQ(vs_roulette_survival(vec3(1.0f), 9u, 4u), 0.95f);  // albedo 1 still ends
  EXPECT_FLOAT_EQ(vs_roulette_survival(vec3(7.0f), 9u, 4u), 0.95f);
  EXPECT_EQ(vs_roulette_survival(vec3(0.0f), 9u, 4u), 0.0f);
}
