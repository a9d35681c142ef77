// The five direction-sampling strategies (sampling/strategies.h), exactly as the
// shaders compile them: every strategy on synthetic visibility maps and
// environments is chi-square tested against its own pdf, its pdf integrates to
// 1, sample() reports the pdf that pdf(direction) gives, and the estimator
// E[f/p] of a light x visibility integral agrees across strategies.
// The direction table and pyramid forms and TwoStep's defensive mixture are tested in
// TestSamplingStrategyForms.cxx.
#include "vsStrategyTest.h"

// ------------------------------------------------------------ chi-square tests

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
