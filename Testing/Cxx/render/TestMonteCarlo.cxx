// The Monte Carlo renderer on the device: every strategy against a deterministic
// quadrature of the single-scattering integral (homogeneous box, constant and
// two-tone skies), the strategies against each other (unbiasedness), and
// reproducibility with a fixed seed.
#include "vsRenderTestScene.h"

#include "sampling/interpolation.h"
#include "sampling/strategies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace vs::shared;
using vstest::RenderScene;

namespace
{
const char* kNames[] = { "Uniform", "Environment", "Visibility", "Combined", "TwoStep" };

double ExitDistance(glm::dvec3 p, glm::dvec3 w, double lo, double hi)
{
  double t = 1e300;
  for (int i = 0; i < 3; ++i)
  {
    if (w[i] > 0)
      t = std::min(t, (hi - p[i]) / w[i]);
    else if (w[i] < 0)
      t = std::min(t, (lo - p[i]) / w[i]);
  }
  return std::max(0.0, t);
}

// Radiance along the ray (x, y, -inf) -> +z through the homogeneous box [0, n]^3 (world = index):
// L = int_0^L T(t) sigma_s int (1/4pi) exp(-sigma exit(x_t, w)) Le(w) dw dt (+ T(L) Le(+z) if visible).
glm::dvec3 Quadrature(double x, double y, double n, double sigma, glm::dvec3 albedo,
  const std::function<glm::dvec3(glm::dvec3)>& Le, bool visible)
{
  const int nt = 64, nth = 48, nph = 96;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < nt; ++i)
  {
    double t = (i + 0.5) * n / nt;
    glm::dvec3 p(x, y, t);
    glm::dvec3 inner(0.0);
    for (int a = 0; a < nth; ++a)
    {
      double th = (a + 0.5) * M_PI / nth;
      for (int b = 0; b < nph; ++b)
      {
        double ph = (b + 0.5) * 2.0 * M_PI / nph;
        glm::dvec3 w(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
        double dw = std::sin(th) * (M_PI / nth) * (2.0 * M_PI / nph);
        inner += Le(w) * std::exp(-sigma * ExitDistance(p, w, 0.0, n)) * dw;
      }
    }
    sum += std::exp(-sigma * t) * sigma * albedo * inner / (4.0 * M_PI) * (n / nt);
  }
  if (visible)
    sum += std::exp(-sigma * n) * Le(glm::dvec3(0, 0, 1));
  return sum;
}
}

// A homogeneous box lit by a constant sky, and by a two-tone sky (bright above, dim below):
// every strategy agrees with the quadrature within 3 standard errors at every pixel.
namespace
{
using vstest::Agreement;
using vstest::Compare;
}

TEST(MonteCarlo, HomogeneousBoxMatchesQuadrature)
{
  const uint32_t n = 16;
  const double sigma = 0.12;
  const glm::vec3 albedo(0.9f, 0.6f, 0.3f);
  struct Sky
  {
    vs::EnvironmentMap map;
    std::function<glm::dvec3(glm::dvec3)> Le;
  };
  Sky skies[] = { { vs::EnvironmentMap::Constant(32, glm::vec3(1.0f)), [](glm::dvec3) { return glm::dvec3(1.0); } },
    { vs::EnvironmentMap::TwoToneSky(32, glm::vec3(2.0f, 1.5f, 1.0f), glm::vec3(0.1f, 0.2f, 0.3f)),
      [](glm::dvec3 w) { return w.z > 0 ? glm::dvec3(2.0, 1.5, 1.0) : glm::dvec3(0.1, 0.2, 0.3); } } };
  const uint32_t W = 4, H = 4;
  const float lo = 1.0f, hi = 14.0f;
  for (const Sky& sky : skies)
  {
    RenderScene scene({ { n + 1, n + 1, n + 1 } }, [](int, int, int) { return 1.0f; }, sigma, albedo, sky.map);
    // Every strategy with ratio tracking; Environment and TwoStep also with the ray-marched shadow
    // rays (VS_TRANSMITTANCE_RAY_MARCHING: exp(-sigma d) from a march, the series' terms 0 here).
    for (uint32_t run = 0; run < 7; ++run)
    {
      const uint32_t strategy = run < 5 ? run : (run == 5 ? VS_STRATEGY_ENVIRONMENT : VS_STRATEGY_TWO_STEP);
      auto p = scene.Params(W, H, lo, hi, strategy, 512, 11u, true);
      if (run >= 5)
        p.transmittance = VS_TRANSMITTANCE_RAY_MARCHING;
      auto [mean, var] = scene.Render(p, 4);
      // Per channel, sum of z^2 over the 16 pixels ~ chi-square(16): reject beyond its 1e-4 quantile (45.1).
      double chi2[3] = { 0, 0, 0 };
      for (uint32_t y = 0; y < H; ++y)
      {
        for (uint32_t x = 0; x < W; ++x)
        {
          // The pixel integrates its footprint (box filter); the integrand is smooth across it: use the centre.
          double wx = lo + (hi - lo) * (x + 0.5) / W, wy = lo + (hi - lo) * (y + 0.5) / H;
          glm::dvec3 ref = Quadrature(wx, wy, n, sigma, glm::dvec3(albedo), sky.Le, true);
          for (int c = 0; c < 3; ++c)
          {
            size_t i = 4 * (y * W + x) + c;
            double se = std::sqrt(var[i] / scene.LastSamples) + 1e-3 * ref[c]; // + the quadrature's error
            double z = (mean[i] - ref[c]) / se;
            chi2[c] += z * z;
          }
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_LT(chi2[c], 45.1) << kNames[strategy] << (run >= 5 ? ", ray marching" : "") << " channel " << c;
      }
    }
  }
}

// The same samples whatever the split into frames and dispatches: a fixed seed gives the same
// image bit for bit (counter-based random numbers, the same compensated additions in the same
// order), with 512 samples asked of one dispatch (TwoStep's samples then pass lavapipe's loop
// limit, 65535 back-edges: the kernel stops at its budget and the pass dispatches again; before the
// budget, 160 or more samples per dispatch gave wrong pixels), 16 frames of 32 one-sample
// dispatches, or dispatches of 7. TwoStep both with the cells' direction table (the default) and
// with the map built at each scatter event.
TEST(MonteCarlo, ReproducibleWhateverTheFrameSplit)
{
  RenderScene scene({ { 12, 10, 9 } }, [](int x, int y, int z) { return float((x + 2 * y + 3 * z) % 5) / 4.0f; }, 0.5,
    glm::vec3(0.8f), vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f),
      glm::vec3(0.2f)));
  const uint32_t total = 512;
  uint32_t catchUps = 0;
  bool usedTable = false;
  auto render = [&](vs::shared::VsMonteCarloParams p, int frames, uint32_t perDispatch, bool table) {
    vs::MonteCarloPass pass(scene.Context);
    pass.SetSamplesPerDispatch(perDispatch);
    pass.SetDirectionTable(table);
    pass.Reset(p.camera.width, p.camera.height);
    for (int f = 0; f < frames; ++f)
      pass.Render(*scene.Volume, *scene.TF, *scene.Majorants, scene.Grid.get(), *scene.Environment, p, {});
    EXPECT_EQ(pass.Samples(), total);
    catchUps = pass.LastCatchUps();
    usedTable = pass.LastUsedDirectionTable();
    return std::make_pair(pass.Mean(), pass.Variance());
  };
  for (uint32_t strategy : { VS_STRATEGY_UNIFORM, VS_STRATEGY_TWO_STEP, VS_STRATEGY_TWO_STEP + 100 })
  {
    const bool table = strategy == VS_STRATEGY_TWO_STEP;
    strategy %= 100;
    const std::string name = std::string(kNames[strategy]) + (table ? " (direction table)" : "");
    auto p = scene.Params(8, 8, -2.0f, 12.0f, strategy, total, 5u, true);
    auto [a, va] = render(p, 1, vs::MonteCarloPass::kMaxSamplesPerDispatch, table);
    EXPECT_EQ(usedTable, table) << name;
    if (strategy == VS_STRATEGY_TWO_STEP)
      EXPECT_GT(catchUps, 0u) << total << " " << name << " samples fit one dispatch's loop budget: the split is not exercised";
    p.samplesPerFrame = 32;
    auto [b, vb] = render(p, total / 32, 1, table);
    auto [c, vc] = render(p, total / 32, 7, table);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a, b) << name << ": " << total << " samples asked of one dispatch against " << total << " dispatches of 1";
    EXPECT_EQ(va, vb) << name;
    EXPECT_EQ(b, c) << name << ": dispatches of 7 samples";
    double sum = 0.0;
    for (float v : a)
      sum += v;
    EXPECT_GT(sum, 0.0) << name << ": an image, not zeros";
  }
}

// The cell-by-cell majorant walk (what dense media take, mc_render.glsl refine_majorant) is unbiased:
// forced everywhere (a refinement depth of 0.05 instead of 32) on a heterogeneous volume, every
// pixel agrees with the brick walk within its standard errors (sum of z^2 over the 64 pixels x 4
// channels with variance ~ chi-square(dof): reject beyond dof + 4 sd + 20, past its 1e-4 quantile).
TEST(MonteCarlo, CellMajorantWalkIsUnbiased)
{
  RenderScene scene({ { 17, 15, 13 } },
    [](int x, int y, int z) { return float((x * 7 + y * 3 + z * 5) % 11) / 10.0f * float(x > 4); }, 2.0,
    glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
  for (uint32_t strategy : { VS_STRATEGY_UNIFORM, VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(8, 8, -2.0f, 18.0f, strategy, 512, 3u, true);
    auto [a, va] = scene.Render(p, 2);
    const double n = scene.LastSamples;
    p.cellWalkDepth = 0.05f;
    p.camera.seed = 4u; // independent samples
    auto [b, vb] = scene.Render(p, 2);
    const Agreement g = Compare(a, va, b, vb, n);
    EXPECT_GT(g.dof, 150) << kNames[strategy];
    EXPECT_LT(g.chi2, g.Bound()) << kNames[strategy];
  }
}

// Splitting is unbiased: 4 and 64 shadow rays per scatter point agree with 1 within the standard errors
// (the same z^2 sum as above), and lower the variance of a sample (same camera rays, more light
// directions per scatter point).
TEST(MonteCarlo, ShadowRaySplittingIsUnbiased)
{
  RenderScene scene({ { 17, 15, 13 } },
    [](int x, int y, int z) { return float((x * 7 + y * 3 + z * 5) % 11) / 10.0f * float(x > 4); }, 2.0,
    glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
  for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(8, 8, -2.0f, 18.0f, strategy, 512, 3u, true);
    auto [a, va] = scene.Render(p, 2);
    const double n = scene.LastSamples;
    p.shadowRays = 4u;
    p.camera.seed = 4u; // independent samples
    auto [b, vb] = scene.Render(p, 2);
    const Agreement g = Compare(a, va, b, vb, n);
    EXPECT_GT(g.dof, 150) << kNames[strategy];
    EXPECT_LT(g.chi2, g.Bound()) << kNames[strategy];
    EXPECT_LT(g.varB, 0.9 * g.varA) << kNames[strategy] << ": 4 shadow rays should lower the variance of a sample";
    // The most the mapper accepts (vtkVisibilitySweepVolumeMapper::SetShadowRays clamps to 64): the
    // rays share the loop budget's tracking steps, so a sample still fits one dispatch (with each
    // ray at the full tracking cap no sample fitted beyond 6 rays, and the render failed).
    p.shadowRays = 64u;
    p.camera.seed = 5u;
    auto [c, vc] = scene.Render(p, 2);
    const Agreement g64 = Compare(a, va, c, vc, n);
    EXPECT_GT(g64.dof, 150) << kNames[strategy];
    EXPECT_LT(g64.chi2, g64.Bound()) << kNames[strategy] << ": 64 shadow rays";
    EXPECT_LT(g64.varB, g.varB) << kNames[strategy] << ": 64 shadow rays should lower the variance further";
  }
}

// The reservoir camera estimator (ratio tracking, one scatter point resampled from every tentative
// collision) is unbiased: its image agrees with delta tracking's within the standard errors, alpha
// included, with the environment seen and not, and it lowers the variance of a sample.
TEST(MonteCarlo, ReservoirCameraIsUnbiased)
{
  RenderScene scene({ { 17, 15, 13 } },
    [](int x, int y, int z) { return float((x * 7 + y * 3 + z * 5) % 11) / 10.0f * float(x > 4); }, 0.5,
    glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
  for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
  {
    for (bool background : { false, true })
    {
      auto p = scene.Params(8, 8, -2.0f, 18.0f, strategy, 512, 3u, true);
      p.background = background ? VS_BACKGROUND_ENVIRONMENT : VS_BACKGROUND_TRANSPARENT;
      auto [a, va] = scene.Render(p, 2);
      const double n = scene.LastSamples;
      p.cameraEstimator = VS_CAMERA_RESERVOIR;
      p.camera.seed = 4u; // independent samples
      auto [b, vb] = scene.Render(p, 2);
      const Agreement g = Compare(a, va, b, vb, n);
      const std::string what = std::string(kNames[strategy]) + (background ? ", environment seen" : ", transparent");
      EXPECT_GT(g.dof, 150) << what;
      EXPECT_LT(g.chi2, g.Bound()) << what;
      std::printf("[ reservoir ] %s: variance per sample %.4g (collision) -> %.4g (reservoir), chi2 %.1f dof %d\n",
        what.c_str(), g.varA, g.varB, g.chi2, g.dof);
      EXPECT_LT(g.varB, g.varA) << what << ": the reservoir should lower the variance of a sample";
    }
  }
}

namespace
{
// The media of the control-extinction and ray-marching tests under a sun, 25 x 23 x 21 voxels:
// 0 dense and heterogeneous, its bricks filled throughout past x = 2; 1 the same with one NaN
// voxel; 2 a voxel checkerboard of 0 and 1 (the extinction swings between 0 and the majorant
// inside every cell).
RenderScene DenseMediumUnderASun(int medium)
{
  return RenderScene({ { 25, 23, 21 } },
    [medium](int x, int y, int z) {
      if (medium == 1 && x == 12 && y == 11 && z == 10)
        return std::numeric_limits<float>::quiet_NaN();
      if (medium == 2)
        return float((x + y + z) % 2);
      return x > 2 ? 0.6f + 0.4f * float((x * 7 + y * 3 + z * 5) % 11) / 10.0f : 0.0f;
    },
    medium == 2 ? 0.3 : 0.15, glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
}
}

// Environment and Uniform sampling run a module without the grid's code (mc_render_env.comp, whose
// pipeline the first image waits for): the same bits as the module with it (here the instrumented
// one, which counts reads and changes nothing else), with or without a grid bound.
TEST(MonteCarlo, TheModuleWithoutTheGridRendersTheSameBits)
{
  RenderScene scene = DenseMediumUnderASun(0);
  for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_UNIFORM })
  {
    auto p = scene.Params(8, 8, -2.0f, 26.0f, strategy, 16, 3u, true);
    scene.CountLookups = false;
    auto [lean, vlean] = scene.Render(p, 2);
    EXPECT_NE(scene.LastPipelineName.find("no grid"), std::string::npos) << scene.LastPipelineName;
    scene.CountLookups = true;
    auto [full, vfull] = scene.Render(p, 2);
    EXPECT_NE(scene.LastPipelineName.find("counting reads"), std::string::npos) << scene.LastPipelineName;
    EXPECT_EQ(lean, full) << kNames[strategy];
    EXPECT_EQ(vlean, vfull) << kNames[strategy];
  }
  scene.CountLookups = false;
}

// Control extinctions (mc_params.h controlExtinction, VS_CONTROL_*): residual ratio tracking of the shadow
// rays and decomposition tracking of the camera rays integrate each brick's smallest extinction
// exactly and track only the rest. Unbiased: on a dense medium whose bricks are filled throughout
// (and one with a NaN voxel, which must get no control) each variant's image agrees with plain
// tracking's within the standard errors, alpha included, and the shadow rays' residual reads fewer
// volume samples at a lower variance.
TEST(MonteCarlo, ControlExtinctionIsUnbiased)
{
  for (bool nan : { false, true })
  {
    RenderScene scene = DenseMediumUnderASun(nan ? 1 : 0);
    scene.CountLookups = true;
    for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
    {
      auto p = scene.Params(8, 8, -2.0f, 26.0f, strategy, 512, 3u, true);
      auto [a, va] = scene.Render(p, 2);
      const double n = scene.LastSamples;
      const uint64_t reads = scene.LastLookups[0];
      for (uint32_t control : { VS_CONTROL_SHADOW, VS_CONTROL_CAMERA, VS_CONTROL_SHADOW | VS_CONTROL_CAMERA })
      {
        p.controlExtinction = control;
        p.camera.seed = 4u + control; // independent samples
        auto [b, vb] = scene.Render(p, 2);
        const Agreement g = Compare(a, va, b, vb, n);
        const std::string what = std::string(kNames[strategy]) + ", control " + std::to_string(control) +
          (nan ? ", a NaN voxel" : "");
        EXPECT_GT(g.dof, 150) << what;
        EXPECT_LT(g.chi2, g.Bound()) << what;
        std::printf("[ control ] %s: volume reads %llu -> %llu, variance per sample %.4g -> %.4g, chi2 %.1f dof %d\n",
          what.c_str(), (unsigned long long)reads, (unsigned long long)scene.LastLookups[0], g.varA, g.varB, g.chi2,
          g.dof);
        if (!nan && (control & VS_CONTROL_SHADOW))
        {
          // The shadow rays' residual tracks at the residual majorant: fewer steps, each read saved.
          // (The camera's control collisions save acceptance tests but read the albedo where they
          // land, so at this medium's high acceptance rate they read about as much.)
          EXPECT_LT(double(scene.LastLookups[0]), 0.9 * double(reads)) << what << ": the control should save reads";
          EXPECT_LT(g.varB, g.varA) << what << ": the residual's weights are closer to 1";
        }
      }
    }
  }
}

// Kettunen et al. 2021's unbiased ray-marching transmittance of the shadow rays (mc_params.h
// transmittance = VS_TRANSMITTANCE_RAY_MARCHING), with and without the shadow rays' control extinction:
// on the dense heterogeneous medium of ControlExtinctionIsUnbiased (and with its NaN voxel, empty
// space to the march) the image agrees with plain ratio tracking's within the standard errors,
// alpha included. The estimate of one shadow ray can be negative or above 1; the image's mean cannot
// tell, only its variance.
TEST(MonteCarlo, RayMarchedTransmittanceIsUnbiased)
{
  // 0, 1: the dense medium, without and with the NaN voxel; 2: a voxel checkerboard of 0 and 1 (the
  // extinction swings between 0 and the majorant inside every cell). What this checks is the march
  // (the control's exact part, the spacing, NaN, the budget): the series' own correction is below
  // what 64 pixels at 1024 samples resolve here (with the series switched off, exp(-march) alone,
  // this test still passed), so the series' unbiasedness is RayMarchingSeries' CPU test of the
  // shader's functions (sampling/ray_marching.h), on a march that is far off.
  for (int medium : { 0, 1, 2 })
  {
    const bool nan = medium == 1;
    RenderScene scene = DenseMediumUnderASun(medium);
    scene.CountLookups = true;
    for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
    {
      auto p = scene.Params(8, 8, -2.0f, 26.0f, strategy, 512, 3u, true);
      auto [a, va] = scene.Render(p, 2);
      const double n = scene.LastSamples;
      const uint64_t reads = scene.LastLookups[0];
      for (uint32_t control : { 0u, VS_CONTROL_SHADOW })
      {
        p.controlExtinction = control;
        p.transmittance = VS_TRANSMITTANCE_RAY_MARCHING;
        p.camera.seed = 9u + control; // independent samples
        auto [b, vb] = scene.Render(p, 2);
        const Agreement g = Compare(a, va, b, vb, n);
        const std::string what = std::string(kNames[strategy]) + ", ray marching, control " +
          std::to_string(control) + (nan ? ", a NaN voxel" : "") + (medium == 2 ? ", checkerboard" : "");
        EXPECT_GT(g.dof, 150) << what;
        EXPECT_LT(g.chi2, g.Bound()) << what;
        for (size_t i = 0; i < b.size(); ++i)
        {
          ASSERT_TRUE(std::isfinite(b[i]) && std::isfinite(vb[i])) << what << " at " << i;
        }
        std::printf("[ ray marching ] %s: volume reads %llu -> %llu, variance per sample %.4g -> %.4g, chi2 %.1f "
                    "dof %d\n",
          what.c_str(), (unsigned long long)reads, (unsigned long long)scene.LastLookups[0], g.varA, g.varB, g.chi2,
          g.dof);
      }
    }
  }
}

// The Sobol sampler (mc_params.h pixelSampler = VS_SAMPLER_SOBOL: each pixel's jitter and light
// directions from its scrambled Sobol sequences) is unbiased: its image agrees with independent
// sampling's within the standard errors (which, computed from the per-sample variance, overstate the
// Sobol mean's error: the check is conservative); and it pays: the mean squared difference between
// two renders of different seeds, twice the variance of a pixel's mean, is smaller than with
// independent samples at the same spp.
TEST(MonteCarlo, SobolSamplerIsUnbiasedAndConvergesFaster)
{
  RenderScene scene({ { 17, 15, 13 } },
    [](int x, int y, int z) { return float((x * 7 + y * 3 + z * 5) % 11) / 10.0f * float(x > 4); }, 2.0,
    glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
  for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(8, 8, -2.0f, 18.0f, strategy, 512, 3u, true);
    auto [a, va] = scene.Render(p, 2);
    const double n = scene.LastSamples;
    p.pixelSampler = VS_SAMPLER_SOBOL;
    p.camera.seed = 4u; // independent scrambles
    auto [b, vb] = scene.Render(p, 2);
    const Agreement g = Compare(a, va, b, vb, n);
    EXPECT_GT(g.dof, 150) << kNames[strategy];
    EXPECT_LT(g.chi2, g.Bound()) << kNames[strategy];

    // Two renders of 64 spp with different seeds, per sampler: their mean squared difference.
    auto msd = [&](uint32_t sampler) {
      auto q = scene.Params(8, 8, -2.0f, 18.0f, strategy, 64, 11u, true);
      q.pixelSampler = sampler;
      double sum = 0.0;
      int count = 0;
      for (uint32_t pair = 0; pair < 4; ++pair)
      {
        q.camera.seed = 100u + 2u * pair;
        auto x = scene.Render(q, 1).first;
        q.camera.seed = 101u + 2u * pair;
        auto y = scene.Render(q, 1).first;
        for (size_t i = 0; i < x.size(); ++i)
        {
          sum += (double(x[i]) - y[i]) * (double(x[i]) - y[i]);
          ++count;
        }
      }
      return sum / count;
    };
    const double independent = msd(VS_SAMPLER_INDEPENDENT), sobol = msd(VS_SAMPLER_SOBOL);
    std::printf("[ sobol ] %s: chi2 %.1f dof %d; squared difference of two 64-spp renders %.4g (independent) -> "
                "%.4g (Sobol), %.2fx\n",
      kNames[strategy], g.chi2, g.dof, independent, sobol, independent / sobol);
    EXPECT_LT(sobol, 0.9 * independent) << kNames[strategy] << ": the Sobol sampler should converge faster";
  }
}

// Nearest interpolation (volume.interpolation = VS_INTERPOLATION_NEAREST): a label map of the scalars 0 and 1 under
// a transfer function opaque only at 0.5 has no medium anywhere, so delta tracking never collides
// (alpha exactly 0 at every pixel) although every brick's majorant (over the scalar range [0, 1])
// is that of 0.5 and the cell walk refines the optically thick bricks. Trilinear (as before) sees
// the blended labels between the stripes.
TEST(MonteCarlo, NearestInterpolationSeesNoBlendedLabels)
{
  RenderScene scene({ { 18, 16, 14 } }, [](int x, int y, int z) { return float((x / 2 + y / 3 + z) % 2); }, 1.0,
    glm::vec3(0.8f), vs::EnvironmentMap::Constant(32, glm::vec3(1.0f)));
  scene.UseHatTransferFunction(40.0);
  for (uint32_t strategy : { VS_STRATEGY_ENVIRONMENT, VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(8, 8, -1.0f, 18.0f, strategy, 16, 5u);
    p.volume.interpolation = VS_INTERPOLATION_NEAREST;
    auto [nearest, vn] = scene.Render(p, 2);
    double maxAlpha = 0.0;
    for (size_t i = 3; i < nearest.size(); i += 4)
    {
      maxAlpha = std::max(maxAlpha, double(nearest[i]));
    }
    EXPECT_EQ(maxAlpha, 0.0) << kNames[strategy] << ": nearest samples never read a blended label";
    p.volume.interpolation = VS_INTERPOLATION_LINEAR;
    auto [linear, vl] = scene.Render(p, 2);
    double meanAlpha = 0.0;
    for (size_t i = 3; i < linear.size(); i += 4)
    {
      meanAlpha += linear[i] / double(linear.size() / 4);
    }
    EXPECT_GT(meanAlpha, 0.5) << kNames[strategy] << ": trilinear samples see the blended labels";
  }
}

// Under nearest interpolation the cell walk's majorant (mc_render.glsl refine_majorant) is the
// largest extinction of the voxels whose halves of the cell a segment reaches: forced everywhere
// (a refinement depth of 0.05) on a heterogeneous volume with NaN voxels (empty under nearest only
// in their own half-cells), every pixel agrees with the brick walk within its standard errors, as
// in CellMajorantWalkIsUnbiased. A trilinear bound of the segment, or a cell with a NaN corner
// taken as empty, is not a majorant of nearest samples and fails this.
TEST(MonteCarlo, NearestCellMajorantWalkIsUnbiased)
{
  RenderScene scene({ { 17, 15, 13 } },
    [](int x, int y, int z) {
      return (x * 5 + y * 3 + z) % 13 == 0 ? std::nanf("") : float((x * 7 + y * 3 + z * 5) % 11) / 10.0f;
    },
    4.0, glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
  for (uint32_t strategy : { VS_STRATEGY_UNIFORM, VS_STRATEGY_ENVIRONMENT })
  {
    auto p = scene.Params(8, 8, -2.0f, 18.0f, strategy, 512, 3u, true);
    p.volume.interpolation = VS_INTERPOLATION_NEAREST;
    auto [a, va] = scene.Render(p, 4);
    const double n = scene.LastSamples;
    p.cellWalkDepth = 0.05f;
    p.camera.seed = 4u; // independent samples
    auto [b, vb] = scene.Render(p, 4);
    const Agreement g = Compare(a, va, b, vb, n);
    std::printf("%s nearest: cell walk against brick walk chi2 %.1f over %d dof\n", kNames[strategy], g.chi2, g.dof);
    EXPECT_GT(g.dof, 150) << kNames[strategy];
    EXPECT_LT(g.chi2, g.Bound()) << kNames[strategy];
  }
}
