// The strategies' other forms (sampling/strategies.h, direction_table.h): the environment pyramid and
// the cells' direction table give the pdf they are chi-square tested against, the table keeps every
// texel of its map, and TwoStep's defensive mixture with Environment sampling matches its pdf and is
// bounded by Environment sampling's.
#include "vsStrategyTest.h"

// ------------------------------------------------------------ chi-square tests

// The render kernel's form of the grid strategies: the map with its sum pyramid.
TEST(SamplingStrategies, PyramidFormsMatchPdf)
{
  for (uint strategy : { VS_STRATEGY_VISIBILITY, VS_STRATEGY_COMBINED, VS_STRATEGY_TWO_STEP })
  {
    for (const NamedMap& vis : kVisibilityMaps)
    {
      EXPECT_TRUE(PyramidStrategyMatchesPdf(strategy, MakeScene(vis, kEnvironments[1], 8, 5)));
    }
    EXPECT_TRUE(PyramidStrategyMatchesPdf(strategy, MakeScene(kVisibilityMaps[2], kEnvironments[3], 16, 6)));
    EXPECT_TRUE(PyramidStrategyMatchesPdf(strategy, MakeScene(kVisibilityMaps[0], kEnvironments[2], 2, 4)));
  }
}

TEST(SamplingStrategies, TableFormsMatchPdf)
{
  for (uint strategy : { VS_STRATEGY_VISIBILITY, VS_STRATEGY_COMBINED, VS_STRATEGY_TWO_STEP })
  {
    for (const NamedMap& vis : kVisibilityMaps)
    {
      EXPECT_TRUE(TableStrategyMatchesPdf(strategy, MakeScene(vis, kEnvironments[1], 8, 5)));
    }
    EXPECT_TRUE(TableStrategyMatchesPdf(strategy, MakeScene(kVisibilityMaps[2], kEnvironments[3], 16, 6)));
    EXPECT_TRUE(TableStrategyMatchesPdf(strategy, MakeScene(kVisibilityMaps[0], kEnvironments[2], 2, 4)));
    EXPECT_TRUE(TableStrategyMatchesPdf(strategy, MakeScene(kVisibilityMaps[3], kEnvironments[3], 4, 4)));
  }
}

// The 16-bit table is the map up to rounding: every texel of positive weight keeps a positive
// probability (else its light would never be sampled: bias), no texel of weight 0 gets one, the
// probabilities add to 1, and each is the exact one to within the rounding of log2 D shares.
TEST(SamplingStrategies, TableKeepsEveryTexelOfTheMap)
{
  for (const NamedMap& vis : kVisibilityMaps)
  {
    for (const NamedEnv& env : kEnvironments)
    {
      for (uint D : { 2u, 4u, 8u, 16u })
      {
        Scene s = MakeScene(vis, env, D, 6);
        for (uint strategy : { VS_STRATEGY_VISIBILITY, VS_STRATEGY_TWO_STEP })
        {
          const Map values = ValuesFor(strategy, s);
          const std::vector<float> pyramid = WithPyramid(values, D);
          const std::vector<uint32_t> table = TableOf(values, D, 0);
          double total = 0.0;
          bool any = false;
          for (uint y = 0; y < D; ++y)
          {
            for (uint x = 0; x < D; ++x)
            {
              const float exact = vs_warp_pyramid_prob(pyramid.data(), D, uvec2(x, y));
              const float p = vs_warp_table_prob(table.data(), 0u, D, uvec2(x, y));
              total += p;
              any = any || values[y * D + x] > 0.0f;
              ASSERT_EQ(values[y * D + x] > 0.0f, p > 0.0f)
                << StrategyName(strategy) << ", " << s.name << ", texel " << x << ", " << y;
              // A texel's probability is the product of its log2 D <= 4 shares, so each share of a
              // texel of probability > 1e-3 is > 1e-3, and rounding it to 1/65535 moves it by at
              // most 0.5 / (65535 x 1e-3) = 0.76% (the stored sum's rounding adds < 0.01%):
              // at most 4 x 0.77% in all.
              if (exact > 1e-3f)
              {
                EXPECT_NEAR(p / exact, 1.0, 0.031) << StrategyName(strategy) << ", " << s.name;
              }
            }
          }
          EXPECT_NEAR(total, any ? 1.0 : 0.0, 1e-5) << StrategyName(strategy) << ", " << s.name;
        }
      }
    }
  }
}

TEST(SamplingStrategies, DefensiveTwoStepMatchesPdf)
{
  for (float alpha : { 0.25f, 0.5f })
  {
    for (bool table : { true, false })
    {
      for (const NamedMap& vis : kVisibilityMaps)
      {
        EXPECT_TRUE(DefensiveMatchesPdf(MakeScene(vis, kEnvironments[1], 8, 5), alpha, table));
      }
      EXPECT_TRUE(DefensiveMatchesPdf(MakeScene(kVisibilityMaps[2], kEnvironments[3], 16, 6), alpha, table));
      EXPECT_TRUE(DefensiveMatchesPdf(MakeScene(kVisibilityMaps[0], kEnvironments[2], 4, 4), alpha, table));
    }
  }
}

// The mixture's point: its pdf never falls below alpha times Environment sampling's, whatever the
// grid says (here a one-hot map: the grid thinks all but one direction dark); alpha 0 is TwoStep,
// alpha 1 Environment sampling.
TEST(SamplingStrategies, DefensiveTwoStepIsBoundedByEnvironmentSampling)
{
  for (const NamedEnv& light : kEnvironments)
  {
    Scene s = MakeScene(kVisibilityMaps[1], light, 8, 6);
    const float* mips = s.mips.data();
    const Map values = ValuesFor(VS_STRATEGY_TWO_STEP, s);
    const std::vector<float> v = WithPyramid(values, 8);
    const std::vector<uint32_t> t = TableOf(values, 8, 0);
    VsRng rng = vs_rng_init(uvec2(4u, 4u), 4u, 4u);
    for (int i = 0; i < 2000; ++i)
    {
      const vec3 d = vs_sample_uniform_sphere(vs_rng_vec2(rng));
      const float env = vs_pdf_environment(mips, 6u, d);
      for (float alpha : { 0.1f, 0.3f })
      {
        ASSERT_GE(vs_pdf_defensive_table(mips, t.data(), 0u, 8u, 6u, alpha, d), alpha * env * (1.0f - 1e-5f))
          << light.name;
        ASSERT_GE(vs_pdf_defensive_pyramid(mips, v.data(), 8u, 6u, alpha, d), alpha * env * (1.0f - 1e-5f))
          << light.name;
      }
      EXPECT_NEAR(vs_pdf_defensive_pyramid(mips, v.data(), 8u, 6u, 0.0f, d),
        vs_pdf_two_step_pyramid(mips, v.data(), 8u, 6u, d),
        1e-6f * (1.0f + vs_pdf_two_step_pyramid(mips, v.data(), 8u, 6u, d)));
      EXPECT_NEAR(vs_pdf_defensive_pyramid(mips, v.data(), 8u, 6u, 1.0f, d), env, 1e-5f * (1.0f + env));
    }
  }
}
