// Full light transport on the device (mc_path.glsl): the white furnace for every strategy and three
// phase functions, Chandrasekhar's semi-infinite medium (all orders, and the first order alone), the
// estimators against each other (light sampling alone, phase sampling alone, both by the power and
// the balance heuristic, every strategy), the phase's direction, reproducibility whatever the split
// into dispatches, and the single-scattering estimator kept at one event.
#include "vsHalfSpace.h"
#include "vsRenderTestScene.h"
#include "vsError.h"

#include "sampling/mc_params.h"
#include "sampling/strategies.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace vs::shared;
using vstest::Against;
using vstest::AgainstConstant;
using vstest::Phantom;
using vstest::RenderScene;

namespace
{
const char* kNames[] = { "Uniform", "Environment", "Visibility", "Combined", "TwoStep" };

// An orthographic camera whose rays travel along (0, sin t, cos t), centred on `centre`, covering
// `half` world units either side: a view of the z = min face at cos(angle) = cos t to its normal.
glm::mat4 ObliqueCamera(glm::vec3 centre, float half, float t)
{
  glm::mat4 m(0.0f);
  m[0] = glm::vec4(half, 0.0f, 0.0f, 0.0f);
  m[1] = glm::vec4(0.0f, half * std::cos(t), -half * std::sin(t), 0.0f);
  m[2] = glm::vec4(0.0f, 100.0f * std::sin(t), 100.0f * std::cos(t), 0.0f);
  m[3] = glm::vec4(centre, 1.0f);
  return m;
}
}

TEST(FullTransport, ChandrasekharHFunction)
{
  // The values Chandrasekhar tabulates (and docs/papers.md quotes), from the test's own solution.
  const double albedo[] = { 0.9, 0.95, 0.99 }, at1[] = { 0.415, 0.536, 0.753 }, atHalf[] = { 0.508, 0.626, 0.815 };
  for (int i = 0; i < 3; ++i)
  {
    vstest::ChandrasekharH H(albedo[i]);
    EXPECT_NEAR(H.Reflected(1.0), at1[i], 1.5e-3) << albedo[i];
    EXPECT_NEAR(H.Reflected(0.5), atHalf[i], 1.5e-3) << albedo[i];
  }
}

// A non-absorbing medium (albedo 1) of any density under a constant sky of radiance 1 has radiance 1
// everywhere, for any phase function: every pixel is 1 within its confidence bound, for every
// strategy and g in {-0.7, 0, 0.7}, with no event limit (Russian roulette ends the paths).
TEST(FullTransport, WhiteFurnace)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 1.2, glm::vec3(1.0f), vs::EnvironmentMap::Constant(32, glm::vec3(1.0f)));
  for (float g : { -0.7f, 0.0f, 0.7f })
  {
    for (uint32_t strategy = 0; strategy < 5; ++strategy)
    {
      // 2048 samples: the paths' weights are heavy-tailed (Russian roulette divides by 0.95 per event
      // at albedo 1), and at 128 a pixel's sample variance underestimated its spread.
      auto p = scene.Params(8, 8, -1.0f, 24.0f, strategy, 1024, 5u, true);
      p.maxEvents = VS_MAX_SCATTERING_EVENTS;
      p.anisotropy = g;
      auto [mean, var] = scene.Render(p, 2);
      const Against r = AgainstConstant(mean, var, scene.LastSamples, 1.0);
      EXPECT_LT(r.chi2, r.Bound()) << kNames[strategy] << " g " << g << " (largest error " << r.maxError << ")";
      EXPECT_GT(r.dof, 100) << "the phantom covers most pixels";
    }
  }
}

// The same furnace with an event limit of 1 and of 2 is darker: the paths' truncation is seen (the
// test would pass a kernel that ignored the events otherwise).
TEST(FullTransport, FurnaceTruncatedIsDarker)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 1.2, glm::vec3(1.0f), vs::EnvironmentMap::Constant(32, glm::vec3(1.0f)));
  double previous = 0.0;
  for (uint32_t events : { 1u, 2u, 4u })
  {
    auto p = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_ENVIRONMENT, 128, 5u, false);
    p.maxEvents = events;
    auto [mean, var] = scene.Render(p, 1);
    double sum = 0.0, alpha = 0.0;
    for (size_t i = 0; i < mean.size(); i += 4)
    {
      sum += mean[i];
      alpha += mean[i + 3];
    }
    const double m = sum / alpha; // the mean radiance of the covered pixels
    EXPECT_LT(m, 0.97) << events << " events";
    EXPECT_GT(m, previous + 0.02) << events << " events";
    previous = m;
  }
}

// Chandrasekhar's half-space: a homogeneous slab of albedo a, isotropic, under a uniform sky of
// radiance 1, seen at the middle of its face from mu = 1 and 0.5. Its other faces are more than 10
// diffusion lengths 1 / (sigma sqrt(3 (1 - a))) away. All orders against 1 - sqrt(1 - a) H_a(mu);
// one event against the first-order term (a / 2)(1 - mu ln(1 + 1 / mu)).
TEST(FullTransport, ChandrasekharHalfSpace)
{
  const double sigma = 4.0;
  const uint32_t nx = 44, nz = 22; // box [0, 43]^2 x [0, 21]: 10 diffusion lengths at a = 0.99 are 14.4
  for (double a : { 0.9, 0.95, 0.99 })
  {
    RenderScene scene({ { nx, nx, nz } }, [](int, int, int) { return 1.0f; }, sigma, glm::vec3(float(a)),
      vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
    const vstest::ChandrasekharH H(a);
    for (double mu : { 1.0, 0.5 })
    {
      for (uint32_t events : { VS_MAX_SCATTERING_EVENTS, 1u })
      {
        auto p = scene.Params(4, 4, 0.0f, 1.0f, VS_STRATEGY_ENVIRONMENT, 2048, 3u, false);
        p.camera.invViewProj = ObliqueCamera(glm::vec3(21.5f, 21.5f, 0.0f), 0.5f, float(std::acos(mu)));
        p.maxEvents = events;
        auto [mean, var] = scene.Render(p, 2);
        double m = 0.0, v = 0.0;
        const double n = double(mean.size() / 4);
        for (size_t i = 0; i < mean.size(); i += 4)
        {
          m += (mean[i] + mean[i + 1] + mean[i + 2]) / 3.0 / n;
          v += var[i] / scene.LastSamples / (n * n); // the channels are equal (grey albedo)
        }
        const double expected = events == 1u ? 0.5 * a * (1.0 - mu * std::log(1.0 + 1.0 / mu)) : H.Reflected(mu);
        const double se = std::sqrt(v);
        EXPECT_LT(se, 0.01) << "too few samples to tell";
        EXPECT_NEAR(m, expected, 4.0 * se + 2e-3)
          << "albedo " << a << " mu " << mu << (events == 1u ? " single scattering" : " all orders");
      }
    }
  }
}

// Light sampling alone, phase sampling alone and both (power and balance heuristics), and every
// strategy, agree pixel by pixel on a heterogeneous medium of coloured albedo under a sun with sky,
// at several g.
TEST(FullTransport, EstimatorsAgree)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 0.8, glm::vec3(0.95f, 0.8f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1.0f, 0.5f, -1.0f)), 20.0, glm::vec3(8.0f),
      glm::vec3(0.3f, 0.4f, 0.6f)));
  for (float g : { -0.5f, 0.0f, 0.6f })
  {
    // Phase sampling alone finds the sun rarely: heavy-tailed, hence 2048 samples.
    auto base = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_ENVIRONMENT, 1024, 21u, false);
    base.maxEvents = 64;
    base.anisotropy = g;
    auto [refMean, refVar] = scene.Render(base, 2);
    const double n = scene.LastSamples;
    struct Variant
    {
      const char* name;
      uint32_t strategy, mis;
    };
    const Variant variants[] = { { "light sampling alone", VS_STRATEGY_ENVIRONMENT, VS_MIS_LIGHT_ONLY },
      { "phase sampling alone", VS_STRATEGY_ENVIRONMENT, VS_MIS_PHASE_ONLY },
      { "balance heuristic", VS_STRATEGY_ENVIRONMENT, VS_MIS_BALANCE },
      { "Uniform", VS_STRATEGY_UNIFORM, VS_MIS_POWER }, { "Visibility", VS_STRATEGY_VISIBILITY, VS_MIS_POWER },
      { "Combined", VS_STRATEGY_COMBINED, VS_MIS_POWER }, { "TwoStep", VS_STRATEGY_TWO_STEP, VS_MIS_POWER } };
    for (const Variant& v : variants)
    {
      auto p = base;
      p.strategy = v.strategy;
      p.mis = v.mis;
      p.camera.seed = 77u;
      auto [mean, var] = scene.Render(p, 2);
      const auto r = vstest::Compare(refMean, refVar, mean, var, n);
      EXPECT_LT(r.chi2, r.Bound()) << v.name << " against Environment sampling with MIS, g " << g;
      EXPECT_GT(r.dof, 100);
    }
  }
}

// g > 0 scatters forward: a thin cloud seen towards the sun is brighter the larger g; seen with the
// sun behind the camera, darker.
TEST(FullTransport, ForwardScatteringBrightensTheViewTowardsTheSun)
{
  for (float sunZ : { 1.0f, -1.0f })
  {
    RenderScene scene({ { 16, 16, 16 } }, [](int, int, int) { return 1.0f; }, 0.05, glm::vec3(0.9f),
      vs::EnvironmentMap::SunDisk(32, glm::vec3(0.0f, 0.0f, sunZ), 10.0, glm::vec3(50.0f), glm::vec3(0.0f)));
    double brightness[3] = { 0.0, 0.0, 0.0 };
    int k = 0;
    for (float g : { -0.6f, 0.0f, 0.6f })
    {
      auto p = scene.Params(4, 4, 2.0f, 13.0f, VS_STRATEGY_ENVIRONMENT, 256, 9u, false);
      p.maxEvents = 8;
      p.anisotropy = g;
      auto [mean, var] = scene.Render(p, 1);
      double m = 0.0;
      for (size_t i = 0; i < mean.size(); i += 4)
        m += mean[i];
      brightness[k++] = m;
    }
    // Single scattering alone would give f(1) ratios of 10 (g 0.6 : 0) and 6.4 (0 : -0.6); multiple
    // scattering (the sun's light scattered twice backwards comes forwards) narrows the second.
    if (sunZ > 0)
    {
      EXPECT_GT(brightness[2], 4.0 * brightness[1]) << "towards the sun, g 0.6 against 0";
      EXPECT_GT(brightness[1], 1.2 * brightness[0]) << "towards the sun, g 0 against -0.6";
    }
    else
    {
      EXPECT_GT(brightness[0], 4.0 * brightness[1]) << "sun behind the camera, g -0.6 against 0";
      EXPECT_GT(brightness[1], 1.2 * brightness[2]) << "sun behind the camera, g 0 against 0.6";
    }
  }
}

// The same bits whatever the split: paths in flight are kept between dispatches exactly. One
// dispatch of all samples (the loop budget splits it), one sample per dispatch, and frames of 3.
TEST(FullTransport, ReproducibleWhateverTheDispatchSplit)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 3.0, glm::vec3(0.99f, 0.97f, 0.95f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
  auto p = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_TWO_STEP, 128, 3u, true);
  p.maxEvents = 256;
  p.anisotropy = 0.3f;
  std::vector<std::vector<float>> images;
  for (int split = 0; split < 3; ++split)
  {
    vs::MonteCarloPass pass(scene.Context);
    pass.SetSamplesPerDispatch(split == 0 ? 4096u : 1u);
    pass.Reset(8, 8);
    auto q = p;
    const int frames = split == 2 ? 8 : 1; // 8 frames of 16
    q.samplesPerFrame = p.samplesPerFrame / uint32_t(frames);
    for (int f = 0; f < frames; ++f)
      pass.Render(*scene.Volume, *scene.TF, *scene.Majorants, scene.Grid.get(), *scene.Environment, q, {});
    EXPECT_EQ(pass.Samples(), 128u);
    if (split == 0)
      EXPECT_GT(pass.LastCatchUps(), 0u) << "128 paths in one dispatch: the loop budget must split them mid-path";
    images.push_back(pass.Mean());
  }
  EXPECT_EQ(images[0], images[1]);
  EXPECT_EQ(images[0], images[2]);
}

// At one event the path estimator is the single-scattering estimator: with an isotropic g below
// VS_HG_ISOTROPIC_G (which selects the path kernel) the image equals the single-scattering kernel's
// to float rounding, for a grid strategy too.
TEST(FullTransport, OneEventIsSingleScattering)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 1.0, glm::vec3(0.9f, 0.7f, 0.5f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, -1, 1)), 8.0, glm::vec3(30.0f), glm::vec3(0.3f)));
  for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(8, 8, -1.0f, 24.0f, strategy, 16, 4u, true);
    p.maxEvents = 1;
    auto [single, v1] = scene.Render(p, 1);
    const std::string singleName = scene.LastPipelineName;
    p.anisotropy = 1e-4f;
    auto [path, v2] = scene.Render(p, 1);
    EXPECT_EQ(singleName.find("full transport"), std::string::npos) << singleName;
    EXPECT_NE(scene.LastPipelineName.find("full transport"), std::string::npos) << scene.LastPipelineName;
    ASSERT_EQ(single.size(), path.size());
    for (size_t i = 0; i < single.size(); ++i)
      EXPECT_NEAR(path[i], single[i], 1e-5 * std::max(1.0f, std::abs(single[i]))) << kNames[strategy] << " " << i;
  }
}

// Bad settings: an error naming the setting, the value and the range; nothing rendered.
TEST(FullTransport, BadSettingsAreErrors)
{
  RenderScene scene({ { 8, 8, 8 } }, [](int, int, int) { return 0.5f; }, 1.0, glm::vec3(0.9f),
    vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  auto expectError = [&](const vs::shared::VsMonteCarloParams& p, const std::string& words) {
    vstest::ExpectInputError(scene, p, words);
  };
  auto p = scene.Params(4, 4, 0.0f, 7.0f, VS_STRATEGY_ENVIRONMENT, 4, 1u);
  for (float g : { 1.0f, -1.0f, 1.5f, std::nanf(""), INFINITY })
  {
    auto q = p;
    q.anisotropy = g;
    expectError(q, "anisotropy");
  }
  auto q = p;
  q.maxEvents = VS_MAX_SCATTERING_EVENTS + 1;
  expectError(q, "MaximumScatteringEvents must be in [1, 100000], got 100001");
}

// A pass asked for many variants holds at most kMaxPipelineVariants of them (issue 35, class 10: a host
// churning settings grew without bound), and a variant it let go is made again when asked for.
TEST(FullTransport, PassHoldsABoundedSetOfPipelines)
{
  RenderScene scene({ { 8, 8, 8 } }, [](int, int, int) { return 0.5f; }, 1.0, glm::vec3(0.9f),
    vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  vs::MonteCarloPass pass(scene.Context);
  pass.Reset(4, 4);
  std::vector<float> first;
  int variants = 0;
  for (uint32_t camera = 0; camera < 2; ++camera)
    for (uint32_t sampler = 0; sampler < 2; ++sampler)
      for (uint32_t control = 0; control < 4; ++control)
        for (uint32_t events : { 1u, 3u })
        {
          auto p = scene.Params(4, 4, 0.0f, 7.0f, VS_STRATEGY_ENVIRONMENT, 1, 1u);
          p.cameraEstimator = camera;
          p.pixelSampler = sampler;
          p.controlExtinction = control;
          p.maxEvents = events;
          pass.Render(*scene.Volume, *scene.TF, *scene.Majorants, scene.Grid.get(), *scene.Environment, p, {});
          ++variants;
          EXPECT_LE(pass.PipelineVariants(), vs::MonteCarloPass::kMaxPipelineVariants);
        }
  EXPECT_EQ(variants, 32);
  EXPECT_EQ(pass.PipelineVariants(), vs::MonteCarloPass::kMaxPipelineVariants);
  // The first variant was let go; asking again makes it again and renders.
  auto p = scene.Params(4, 4, 0.0f, 7.0f, VS_STRATEGY_ENVIRONMENT, 1, 1u);
  p.maxEvents = 1;
  pass.Render(*scene.Volume, *scene.TF, *scene.Majorants, scene.Grid.get(), *scene.Environment, p, {});
  EXPECT_EQ(pass.Samples(), 33u);
}
