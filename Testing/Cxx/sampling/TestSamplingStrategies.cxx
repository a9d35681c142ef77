// The five direction-sampling strategies (sampling/strategies.h), exactly as the
// shaders compile them: every strategy on synthetic visibility maps and
// environments is chi-square tested against its own pdf, its pdf integrates to
// 1, sample() reports the pdf that pdf(direction) gives, and the estimator
// E[f/p] of a light x visibility integral agrees across strategies.
#include "sampling/rng.h"
#include "sampling/strategies.h"
#include "vsChiSquare.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace vs::shared;

namespace
{

using Map = std::array<float, 256>; // D x D, index y*D + x

const char* StrategyName(uint s)
{
  static const char* names[] = { "uniform", "environment", "visibility", "combined", "two-step" };
  return names[s];
}

// ------------------------------------------------------- visibility maps

Map RandomVisibility(uint D)
{
  Map m{};
  VsRng rng = vs_rng_init(uvec2(D, 1u), 2u, 3u);
  for (uint i = 0; i < D * D; ++i)
  {
    m[i] = vs_rng_float(rng);
  }
  return m;
}

Map OneHotVisibility(uint D)
{
  Map m{};
  m[(D / 4) * D + D - 2] = 1.0f;
  return m;
}

// Mostly occluded, a few open directions, plus the sweep's ε = 0.01.
Map EpsilonFloorVisibility(uint D)
{
  Map m{};
  for (uint i = 0; i < D * D; ++i)
  {
    m[i] = 0.01f + (i % 5u == 1u ? 0.8f : 0.0f);
  }
  return m;
}

Map NearZeroVisibility(uint D)
{
  Map m = RandomVisibility(D);
  for (uint i = 0; i < D * D; i += 2)
  {
    m[i] = 1e-30f;
  }
  return m;
}

struct NamedMap
{
  const char* name;
  Map (*make)(uint);
};

const NamedMap kVisibilityMaps[] = { { "random", RandomVisibility },
  { "one-hot", OneHotVisibility }, { "epsilon floor", EpsilonFloorVisibility },
  { "near zero", NearZeroVisibility } };

// --------------------------------------------------------- environments
// Leaves are luminances of the N x N equal-area octahedral map, at texel centres.

const vec3 kSunDirection = glm::normalize(vec3(0.3f, -0.4f, 0.8f));

template<typename F>
std::vector<float> EnvFromFunction(uint K, F luminance)
{
  const uint n = 1u << K;
  std::vector<float> leaves(n * n);
  for (uint y = 0; y < n; ++y)
  {
    for (uint x = 0; x < n; ++x)
    {
      leaves[y * n + x] = luminance(vs_texel_dir(uvec2(x, y), n), uvec2(x, y), n);
    }
  }
  return leaves;
}

std::vector<float> ConstantEnv(uint K)
{
  return EnvFromFunction(K, [](vec3, uvec2, uint) { return 1.0f; });
}

// A dim sky and a small sun (4 degrees across) at least one texel wide, 1e4 x brighter.
std::vector<float> SunEnv(uint K)
{
  return EnvFromFunction(K,
    [](vec3 d, uvec2 t, uint n)
    {
      bool sun = glm::dot(d, kSunDirection) > std::cos(glm::radians(2.0f)) ||
                 t == vs_dir_to_texel(kSunDirection, n);
      return sun ? 2000.0f : 0.2f;
    });
}

std::vector<float> TwoToneEnv(uint K)
{
  return EnvFromFunction(K, [](vec3 d, uvec2, uint) { return d.z > 0.0f ? 1.0f : 0.05f; });
}

// Random light, zero over whole subtrees: the level-1 quadrant (0,0) and the
// level-3 node (5,6).
std::vector<float> ZeroSubtreeEnv(uint K)
{
  VsRng rng = vs_rng_init(uvec2(9u, 9u), 9u, 9u);
  return EnvFromFunction(K,
    [&](vec3, uvec2 t, uint n)
    {
      float v = vs_rng_float(rng) + 0.1f;
      bool quadrant = t.x < n / 2 && t.y < n / 2;
      bool node = n >= 8 && t.x / (n / 8) == 5u && t.y / (n / 8) == 6u;
      return quadrant || node ? 0.0f : v;
    });
}

struct NamedEnv
{
  const char* name;
  std::vector<float> (*make)(uint);
};

const NamedEnv kEnvironments[] = { { "constant", ConstantEnv }, { "sun", SunEnv },
  { "two-tone", TwoToneEnv }, { "zero subtrees", ZeroSubtreeEnv } };

// ----------------------------------------------------------------- scenes

struct Scene
{
  std::string name;
  uint D = 8; // direction resolution of the visibility / product map
  uint K = 5; // env quadtree levels: N = 2^K
  Map visibility{};
  Map product{};
  std::vector<float> mips;
};

Scene MakeScene(const NamedMap& vis, const NamedEnv& env, uint D, uint K)
{
  Scene s;
  s.name = std::string(vis.name) + " visibility, " + env.name + " environment, D " +
           std::to_string(D) + ", K " + std::to_string(K);
  s.D = D;
  s.K = K;
  s.visibility = vis.make(D);
  s.mips = vstest::BuildEnvMips(env.make(K), K);
  for (uint y = 0; y < D; ++y)
  {
    for (uint x = 0; x < D; ++x)
    {
      s.product[y * D + x] = vs_product_weight(s.mips.data(), s.visibility[y * D + x], uvec2(x, y), D);
    }
  }
  return s;
}

// The strategy's map: visibility for Visibility, the product otherwise.
Map ValuesFor(uint strategy, const Scene& s)
{
  return strategy == VS_STRATEGY_VISIBILITY ? s.visibility : s.product;
}

// sample() and pdf() of a strategy through the dispatchers.
struct Sampler
{
  const float* mips; // the scene's env mips (warp.h)
  uint strategy;
  Map values;
  uint D, K;

  vec3 Sample(vec2 u, float& pdf)
  {
    return vs_sample_direction(mips, strategy, values.data(), D, K, u, pdf);
  }
  float Pdf(vec3 dir)
  {
    return vs_pdf_direction(mips, strategy, values.data(), D, K, dir);
  }
};

Sampler MakeSampler(uint strategy, const Scene& s)
{
  return Sampler{ s.mips.data(), strategy, ValuesFor(strategy, s), s.D, s.K };
}

testing::AssertionResult StrategyMatchesPdf(uint strategy, const Scene& s)
{
  Sampler sampler = MakeSampler(strategy, s);
  vstest::SamplerTestOptions o;
  o.bins =
    64; // finer than the env leaves (K <= 5) and map texels (D <= 16): tests uniformity within them
  o.sub = 2;
  o.samples = 60000;
  o.seed = strategy * 100u + s.D + s.K;
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf([&](vec2 u, float& pdf) { return sampler.Sample(u, pdf); },
           [&](vec3 d) { return sampler.Pdf(d); }, o)
         << " (" << StrategyName(strategy) << ", " << s.name << ")";
}

// The map with its sum pyramid behind it (warp.h), as the render kernel builds it.
std::vector<float> WithPyramid(const Map& values, uint D)
{
  std::vector<float> v((4 * D * D - 1) / 3, 0.0f);
  std::copy(values.begin(), values.begin() + D * D, v.begin());
  for (uint size = D / 2; size > 0; size /= 2)
  {
    for (uint i = 0; i < size * size; ++i)
    {
      v[vs_pyramid_offset(D, size) + i] = vs_pyramid_parent(v.data(), D, 2 * size, uvec2(i % size, i / size));
    }
  }
  return v;
}

// The same strategy through the pyramid form of the map (the render kernel's, warp.h).
testing::AssertionResult PyramidStrategyMatchesPdf(uint strategy, const Scene& s)
{
  const std::vector<float> v = WithPyramid(ValuesFor(strategy, s), s.D);
  vstest::SamplerTestOptions o;
  o.bins = 64;
  o.sub = 2;
  o.samples = 60000;
  o.seed = strategy * 100u + s.D + s.K + 7u;
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf(
           [&](vec2 u, float& pdf)
           { return vs_sample_direction_pyramid(s.mips.data(), strategy, v.data(), s.D, s.K, u, pdf); },
           [&](vec3 d) { return vs_pdf_direction_pyramid(s.mips.data(), strategy, v.data(), s.D, s.K, d); }, o)
         << " (pyramid, " << StrategyName(strategy) << ", " << s.name << ")";
}

// The cell's direction table (direction_table.h), packed node by node from the pyramid, behind
// `pad` entries of another cell (so that `base` is exercised).
std::vector<uint32_t> TableOf(const Map& values, uint D, uint pad)
{
  const std::vector<float> v = WithPyramid(values, D);
  std::vector<uint32_t> table(pad, 0xdeadbeefu);
  for (uint level = 0; (1u << level) < D; ++level)
  {
    const uint n = 1u << level;
    for (uint i = 0; i < n * n; ++i)
    {
      const uvec2 node = vs_table_node_from_pyramid(v.data(), D, level, uvec2(i % n, i / n));
      table.push_back(node.x);
      table.push_back(node.y);
    }
  }
  return table;
}

// The same strategy through the cell's precomputed table (the render kernel's default form).
testing::AssertionResult TableStrategyMatchesPdf(uint strategy, const Scene& s)
{
  const uint pad = 5;
  const std::vector<uint32_t> table = TableOf(ValuesFor(strategy, s), s.D, pad);
  if (table.size() != pad + 2 * vs_table_nodes(s.D))
  {
    return testing::AssertionFailure() << "table of " << table.size() - pad << " uints, expected "
                                       << 2 * vs_table_nodes(s.D);
  }
  vstest::SamplerTestOptions o;
  o.bins = 64;
  o.sub = 2;
  o.samples = 60000;
  o.seed = strategy * 100u + s.D + s.K + 11u;
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf(
           [&](vec2 u, float& pdf)
           { return vs_sample_direction_table(s.mips.data(), strategy, table.data(), pad, s.D, s.K, u, pdf); },
           [&](vec3 d) { return vs_pdf_direction_table(s.mips.data(), strategy, table.data(), pad, s.D, s.K, d); },
           o)
         << " (table, " << StrategyName(strategy) << ", " << s.name << ")";
}

// The defensive mixture of TwoStep with Environment sampling, from the table or the pyramid.
testing::AssertionResult DefensiveMatchesPdf(const Scene& s, float alpha, bool table)
{
  const Map values = ValuesFor(VS_STRATEGY_TWO_STEP, s);
  const std::vector<uint32_t> t = TableOf(values, s.D, 3);
  const std::vector<float> v = WithPyramid(values, s.D);
  vstest::SamplerTestOptions o;
  o.bins = 64;
  o.sub = 2;
  o.samples = 60000;
  o.seed = s.D + s.K + uint(alpha * 100.0f) + (table ? 1u : 0u);
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf(
           [&](vec2 u, float& pdf) {
             return table ? vs_sample_defensive_table(s.mips.data(), t.data(), 3u, s.D, s.K, alpha, u, pdf)
                          : vs_sample_defensive_pyramid(s.mips.data(), v.data(), s.D, s.K, alpha, u, pdf);
           },
           [&](vec3 d) {
             return table ? vs_pdf_defensive_table(s.mips.data(), t.data(), 3u, s.D, s.K, alpha, d)
                          : vs_pdf_defensive_pyramid(s.mips.data(), v.data(), s.D, s.K, alpha, d);
           },
           o)
    << " (defensive, alpha " << alpha << (table ? ", table, " : ", pyramid, ") << s.name << ")";
}

} // namespace

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

TEST(SamplingStrategies, UniformMatchesPdf)
{
  Scene s = MakeScene(kVisibilityMaps[0], kEnvironments[0], 8, 5);
  EXPECT_TRUE(StrategyMatchesPdf(VS_STRATEGY_UNIFORM, s));
}

TEST(SamplingStrategies, EnvironmentMatchesPdf)
{
  for (const NamedEnv& env : kEnvironments)
  {
    EXPECT_TRUE(
      StrategyMatchesPdf(VS_STRATEGY_ENVIRONMENT, MakeScene(kVisibilityMaps[0], env, 8, 5)));
  }
}

TEST(SamplingStrategies, VisibilityMatchesPdf)
{
  for (const NamedMap& vis : kVisibilityMaps)
  {
    EXPECT_TRUE(StrategyMatchesPdf(VS_STRATEGY_VISIBILITY, MakeScene(vis, kEnvironments[0], 8, 5)));
  }
  for (uint D : { 4u, 16u })
  {
    EXPECT_TRUE(StrategyMatchesPdf(
      VS_STRATEGY_VISIBILITY, MakeScene(kVisibilityMaps[2], kEnvironments[0], D, 6)));
  }
}

TEST(SamplingStrategies, CombinedMatchesPdf)
{
  for (const NamedMap& vis : kVisibilityMaps)
  {
    for (const NamedEnv& env : kEnvironments)
    {
      EXPECT_TRUE(StrategyMatchesPdf(VS_STRATEGY_COMBINED, MakeScene(vis, env, 8, 5)));
    }
  }
  for (uint D : { 4u, 16u })
  {
    EXPECT_TRUE(StrategyMatchesPdf(
      VS_STRATEGY_COMBINED, MakeScene(kVisibilityMaps[0], kEnvironments[1], D, 6)));
  }
}

TEST(SamplingStrategies, TwoStepMatchesPdf)
{
  for (const NamedMap& vis : kVisibilityMaps)
  {
    for (const NamedEnv& env : kEnvironments)
    {
      EXPECT_TRUE(StrategyMatchesPdf(VS_STRATEGY_TWO_STEP, MakeScene(vis, env, 8, 5)));
    }
  }
  // Other direction resolutions, and an env no finer than the map (no descent).
  EXPECT_TRUE(StrategyMatchesPdf(
    VS_STRATEGY_TWO_STEP, MakeScene(kVisibilityMaps[0], kEnvironments[1], 4, 5)));
  EXPECT_TRUE(StrategyMatchesPdf(
    VS_STRATEGY_TWO_STEP, MakeScene(kVisibilityMaps[2], kEnvironments[3], 16, 6)));
  EXPECT_TRUE(StrategyMatchesPdf(
    VS_STRATEGY_TWO_STEP, MakeScene(kVisibilityMaps[0], kEnvironments[3], 8, 3)));
  EXPECT_TRUE(StrategyMatchesPdf(
    VS_STRATEGY_TWO_STEP, MakeScene(kVisibilityMaps[3], kEnvironments[2], 16, 4)));
}

// ------------------------------------------------------ pdf properties

TEST(SamplingStrategies, PdfsIntegrateToOne)
{
  for (const NamedMap& vis : kVisibilityMaps)
  {
    for (const NamedEnv& env : kEnvironments)
    {
      for (uint D : { 4u, 8u, 16u })
      {
        Scene s = MakeScene(vis, env, D, 7);
        for (uint strategy = 0; strategy < 5; ++strategy)
        {
          Sampler sampler = MakeSampler(strategy, s);
          // Midpoint rule at the env resolution: exact for these piecewise
          // constant pdfs, up to float rounding.
          double integral = vstest::IntegratePdf([&](vec3 d) { return sampler.Pdf(d); }, 128, 1);
          EXPECT_NEAR(integral, 1.0, 1e-5) << StrategyName(strategy) << ", " << s.name;
        }
      }
    }
  }
}

TEST(SamplingStrategies, SampledPdfIsPdfOfDirection)
{
  // Far from texel edges the two agree bit for bit (same arithmetic).
  Scene s = MakeScene(kVisibilityMaps[3], kEnvironments[1], 8, 6);
  VsRng rng = vs_rng_init(uvec2(5u, 5u), 5u, 5u);
  for (uint strategy = 0; strategy < 5; ++strategy)
  {
    Sampler sampler = MakeSampler(strategy, s);
    int exact = 0, atEdge = 0, n = 20000;
    for (int i = 0; i < n; ++i)
    {
      float pdf;
      vec3 d = sampler.Sample(vs_rng_vec2(rng), pdf);
      if (vstest::NearTexelEdge(vs_dir_to_octa(d), 64, 1e-5))
      {
        ++atEdge;
        continue;
      }
      exact += pdf == sampler.Pdf(d);
    }
    EXPECT_EQ(exact, n - atEdge) << StrategyName(strategy);
    EXPECT_LT(atEdge, n / 100) << StrategyName(strategy);
  }
}

TEST(SamplingStrategies, DispatchMatchesNamedFunctions)
{
  Scene s = MakeScene(kVisibilityMaps[2], kEnvironments[1], 8, 6);
  const float* mips = s.mips.data();
  Map vis = s.visibility, prod = s.product;
  VsRng rng = vs_rng_init(uvec2(2u, 5u), 5u, 5u);
  for (int i = 0; i < 500; ++i)
  {
    vec2 u = vs_rng_vec2(rng);
    float p0, p1;
    vec3 named[5], dispatched[5];
    float namedPdf[5], dispatchedPdf[5];
    named[0] = vs_sample_uniform(u, namedPdf[0]);
    named[1] = vs_sample_environment(mips, 6u, u, namedPdf[1]);
    named[2] = vs_sample_tabulated(vis.data(), 8u, u, namedPdf[2]);
    named[3] = vs_sample_tabulated(prod.data(), 8u, u, namedPdf[3]);
    named[4] = vs_sample_two_step(mips, prod.data(), 8u, 6u, u, namedPdf[4]);
    for (uint st = 0; st < 5; ++st)
    {
      Map values = ValuesFor(st, s);
      dispatched[st] = vs_sample_direction(mips, st, values.data(), 8u, 6u, u, dispatchedPdf[st]);
      ASSERT_EQ(named[st], dispatched[st]) << StrategyName(st);
      ASSERT_EQ(namedPdf[st], dispatchedPdf[st]) << StrategyName(st);
    }
    vec3 d = named[4];
    EXPECT_EQ(vs_pdf_uniform(d), vs_pdf_direction(mips, 0u, vis.data(), 8u, 6u, d));
    EXPECT_EQ(vs_pdf_environment(mips, 6u, d), vs_pdf_direction(mips, 1u, vis.data(), 8u, 6u, d));
    EXPECT_EQ(vs_pdf_tabulated(vis.data(), 8u, d), vs_pdf_direction(mips, 2u, vis.data(), 8u, 6u, d));
    EXPECT_EQ(vs_pdf_tabulated(prod.data(), 8u, d), vs_pdf_direction(mips, 3u, prod.data(), 8u, 6u, d));
    EXPECT_EQ(
      vs_pdf_two_step(mips, prod.data(), 8u, 6u, d), vs_pdf_direction(mips, 4u, prod.data(), 8u, 6u, d));
    // The same at D = 16.
    Map vis16 = RandomVisibility(16);
    EXPECT_EQ(vs_sample_tabulated(vis16.data(), 16u, u, p0),
      vs_sample_direction(mips, 2u, vis16.data(), 16u, 6u, u, p1));
    EXPECT_EQ(p0, p1);
    EXPECT_EQ(vs_sample_two_step(mips, vis16.data(), 16u, 6u, u, p0),
      vs_sample_direction(mips, 4u, vis16.data(), 16u, 6u, u, p1));
    EXPECT_EQ(p0, p1);
    EXPECT_EQ(vs_pdf_two_step(mips, vis16.data(), 16u, 6u, d),
      vs_pdf_direction(mips, 4u, vis16.data(), 16u, 6u, d));
  }
}

// An all-zero map or environment yields pdf 0: "no sample", never NaN.
TEST(SamplingStrategies, NothingToSampleGivesPdfZero)
{
  const uint K = 6, n = 1u << K;
  std::vector<float> mips = vstest::BuildEnvMips(std::vector<float>(n * n, 0.0f), K);
  Map zero{};
  for (uint strategy = 1; strategy < 5; ++strategy)
  {
    for (vec2 u : { vec2(0.0f), vec2(0.5f, 0.2f), vec2(VS_ONE_MINUS_EPSILON) })
    {
      float pdf8 = -1.0f, pdf16 = -1.0f;
      vec3 a = vs_sample_direction(mips.data(), strategy, zero.data(), 8u, K, u, pdf8);
      vec3 b = vs_sample_direction(mips.data(), strategy, zero.data(), 16u, K, u, pdf16);
      EXPECT_EQ(pdf8, 0.0f) << StrategyName(strategy);
      EXPECT_EQ(pdf16, 0.0f) << StrategyName(strategy);
      EXPECT_TRUE(std::isfinite(glm::length(a)) && std::isfinite(glm::length(b)));
      EXPECT_EQ(vs_pdf_direction(mips.data(), strategy, zero.data(), 8u, K, a), 0.0f);
    }
  }
}

// TwoStep never picks a leaf with zero light, even when the visibility does
// not vanish there; its pdf is 0 exactly where light x (visibility > 0) is 0.
TEST(SamplingStrategies, TwoStepAvoidsUnlitLeaves)
{
  Scene s = MakeScene(kVisibilityMaps[2], kEnvironments[3], 8, 6);
  const uint n = 64, leafLevelOffset = vs_env_level_offset(6u);
  Sampler sampler = MakeSampler(VS_STRATEGY_TWO_STEP, s);
  VsRng rng = vs_rng_init(uvec2(3u, 3u), 3u, 3u);
  for (int i = 0; i < 20000; ++i)
  {
    float pdf;
    vec3 d = sampler.Sample(vs_rng_vec2(rng), pdf);
    vec2 uv = vs_dir_to_octa(d);
    uvec2 leaf = vs_dir_to_texel(d, n);
    if (!vstest::NearTexelEdge(uv, n))
    {
      ASSERT_GT(s.mips[leafLevelOffset + leaf.y * n + leaf.x], 0.0f);
    }
  }
  for (uint y = 0; y < n; ++y)
  {
    for (uint x = 0; x < n; ++x)
    {
      float light = s.mips[leafLevelOffset + y * n + x];
      float pdf = sampler.Pdf(vs_texel_dir(uvec2(x, y), n));
      EXPECT_EQ(pdf > 0.0f, light > 0.0f) << x << "," << y;
    }
  }
}

// --------------------------------------------------------- unbiasedness

namespace
{

// The "true" visibility of a synthetic scatter point: smooth, never 0, and
// not what the tabulated map says exactly (that is only its texel average).
float TrueVisibility(vec3 d)
{
  float c = glm::max(0.0f, glm::dot(d, glm::normalize(vec3(-0.2f, 0.5f, 0.6f))));
  return 0.02f + c * c * c;
}

} // namespace

// E[L(ω) V(ω) / p(ω)] = ∫ L V dω for every strategy: catches a pdf that is 0
// where the integrand is not (which a chi-square test of the sampler against
// its own pdf cannot see).
TEST(SamplingStrategies, EstimatorsAreUnbiased)
{
  const uint D = 8, K = 6, N = 1u << K, sub = 4;
  for (const NamedEnv& env : kEnvironments)
  {
    SCOPED_TRACE(env.name);
    std::vector<float> leaves = env.make(K);
    // Reference integral and texel-averaged visibility (+ ε), at 4x4 points per leaf.
    double reference = 0.0;
    Map visibility{};
    const double cell = 4.0 * M_PI / double(N * sub * N * sub);
    for (uint y = 0; y < N * sub; ++y)
    {
      for (uint x = 0; x < N * sub; ++x)
      {
        vec3 d = vs_octa_to_dir((vec2(x, y) + 0.5f) / float(N * sub));
        double v = TrueVisibility(d);
        reference += leaves[(y / sub) * N + x / sub] * v * cell;
        visibility[(y / (N * sub / D)) * D + x / (N * sub / D)] +=
          float(v / double(N * sub / D * N * sub / D));
      }
    }
    for (uint i = 0; i < D * D; ++i)
    {
      visibility[i] += 0.01f;
    }
    std::vector<float> mips = vstest::BuildEnvMips(leaves, K);
    Map product{};
    for (uint i = 0; i < D * D; ++i)
    {
      product[i] = vs_product_weight(mips.data(), visibility[i], uvec2(i % D, i / D), D);
    }
    for (uint strategy = 0; strategy < 5; ++strategy)
    {
      Map values = strategy == VS_STRATEGY_VISIBILITY ? visibility : product;
      VsRng rng = vs_rng_init(uvec2(strategy, 7u), 1u, 2u);
      const int samples = 50000;
      double sum = 0.0, sumSq = 0.0;
      for (int i = 0; i < samples; ++i)
      {
        float pdf;
        vec3 d = vs_sample_direction(mips.data(), strategy, values.data(), 8u, K, vs_rng_vec2(rng), pdf);
        uvec2 leaf = vs_dir_to_texel(d, N);
        double f = pdf > 0.0f ? leaves[leaf.y * N + leaf.x] * TrueVisibility(d) / pdf : 0.0;
        sum += f;
        sumSq += f * f;
      }
      double mean = sum / samples,
             sigma = std::sqrt(std::max(0.0, sumSq / samples - mean * mean) / samples);
      EXPECT_NEAR(mean, reference, 5.0 * sigma + 2e-3 * reference)
        << StrategyName(strategy) << " sigma " << sigma;
    }
  }
}
