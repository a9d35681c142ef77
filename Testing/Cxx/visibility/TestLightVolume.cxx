// The light volume (vsLightVolume.h): the environment light reaching each visibility cell,
// sum_n V(cell, n) E_n, against the analytic sum and integral for a homogeneous box, exactly 4 pi L
// without a volume, E_n against the renderer's own lookup integrated over each grid texel, and
// rebuilt only when the grid, the environment or the intensity changes.
#include "vsVisibilityTestScene.h"

#include "vsDeviceEnvironment.h"
#include "vsEnvironmentMap.h"
#include "vsError.h"
#include "vsLightVolume.h"
#include "vsSweepPlan.h"
#include "sampling/octahedral.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using vs::VisibilityGridParameters;
using vstest::VisibilityScene;

namespace
{
const double Pi = 3.14159265358979323846;

glm::dvec3 CellCentre(const vs::VisibilityGrid& grid, const vs::VolumeGeometry& g, uint32_t x, uint32_t y, uint32_t z)
{
  return glm::dvec3(g.BoxMin) + (glm::dvec3(x, y, z) + 0.5) * glm::dvec3(grid.CellSize());
}

glm::dvec3 Texel(const std::vector<float>& rgba, const vs::VisibilityGrid& grid, uint32_t x, uint32_t y, uint32_t z)
{
  const auto c = grid.Cells();
  const size_t i = 4 * ((size_t(z) * c[1] + y) * c[0] + x);
  return glm::dvec3(rgba[i], rgba[i + 1], rgba[i + 2]);
}

vs::LatLongImage MakeLatLong(int w, int h, const std::function<glm::vec3(glm::dvec3)>& f)
{
  vs::LatLongImage img;
  img.Width = w;
  img.Height = h;
  img.RGB.resize(3 * size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
    {
      const glm::vec3 c = f(glm::dvec3(vs::LatLongToDirection((i + 0.5) / w, (j + 0.5) / h)));
      for (int k = 0; k < 3; ++k)
        img.RGB[3 * (size_t(j) * w + i) + k] = c[k];
    }
  return img;
}
}

// A homogeneous box (sigma per voxel, world = index) under a constant environment L: the light volume
// at cell centre x is L sum_n (4 pi / D^2) exp(-sigma d(x, w_n)), d the exit distance along the grid's
// direction w_n, up to the grid's error; and close to L times the integral of exp(-sigma d(x, w)) over
// the sphere, within the grid's angular discretisation (one value per texel).
TEST(LightVolume, HomogeneousBoxUnderConstantSkyIsAnalytic)
{
  const double sigma = 0.05;
  const glm::dvec3 L(0.5, 1.0, 2.0);
  VisibilityScene scene({ { 33, 33, 33 } }, [](int, int, int) { return 1.0f; }, sigma);
  const vs::DeviceEnvironment env(scene.Context, vs::EnvironmentMap::Constant(16, glm::vec3(L)), 8);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.Filtering = false;
  const uint32_t D = p.DirectionResolution, DD = D * D;
  const double texelSolidAngle = 4.0 * Pi / DD;
  auto depth = [&](glm::dvec3 x, glm::dvec3 w)
  { return sigma * vstest::ExitDistance(x, w, glm::dvec3(0.0), glm::dvec3(32.0)); };

  // The brute-force grid is exact to 1e-4 per entry (TestVisibilityGrid HomogeneousBoxIsAnalytic), the
  // sweep's mean error 2e-3 and its largest 0.08: the light volume of a cell is off by at most
  // sum_n (4 pi / D^2) L |dV_n|, i.e. 4 pi L times the cell's mean |dV| over its directions.
  struct Case
  {
    VisibilityGridParameters::Method Method;
    double MaxPerCell, MeanPerCell; // fractions of 4 pi L
  };
  for (const Case& c : { Case{ VisibilityGridParameters::Method::BruteForce, 1e-4, 1e-4 },
         Case{ VisibilityGridParameters::Method::Sweep, 0.08, 2e-3 } })
  {
    p.Algorithm = c.Method;
    vs::VisibilityGrid grid(scene.Context);
    scene.Grid(grid, p);
    vs::LightVolume light(scene.Context);
    ASSERT_TRUE(light.Update(grid, env, 1.0));
    const std::vector<float> rgba = light.Download();
    const auto cells = grid.Cells();
    ASSERT_EQ(rgba.size(), 4u * cells[0] * cells[1] * cells[2]);
    double worstSum = 0.0, meanSum = 0.0, worstIntegral = 0.0, worstIntegralExcess = 0.0;
    size_t count = 0;
    for (uint32_t z = 0; z < cells[2]; ++z)
      for (uint32_t y = 0; y < cells[1]; ++y)
        for (uint32_t x = 0; x < cells[0]; ++x)
        {
          const glm::dvec3 centre = CellCentre(grid, scene.Geometry, x, y, z);
          // The grid's own sum: its direction centres, each with the texel's solid angle.
          double sum = 0.0;
          // The finer integral: 8 x 8 equal-area sub-texels per texel; and the most the grid's one value
          // per texel can miss it by, sum_n (4 pi / D^2) (max - min of the integrand over texel n).
          double integral = 0.0, discretisation = 0.0;
          for (uint32_t n = 0; n < DD; ++n)
          {
            sum += texelSolidAngle * std::exp(-depth(centre, glm::dvec3(vs::SweepPlan::Direction(n, D))));
            double lo = 1e300, hi = -1e300, mean = 0.0;
            const int sub = 8;
            for (int b = 0; b < sub; ++b)
              for (int a = 0; a < sub; ++a)
              {
                const glm::vec2 uv((float(n % D) + (a + 0.5f) / sub) / float(D), (float(n / D) + (b + 0.5f) / sub) / float(D));
                const double f = std::exp(-depth(centre, glm::dvec3(vs::shared::vs_octa_to_dir(uv))));
                lo = std::min(lo, f);
                hi = std::max(hi, f);
                mean += f / (sub * sub);
              }
            integral += texelSolidAngle * mean;
            discretisation += texelSolidAngle * (hi - lo);
          }
          const glm::dvec3 got = Texel(rgba, grid, x, y, z);
          for (int k = 0; k < 3; ++k)
          {
            const double e = std::abs(got[k] - L[k] * sum) / (4.0 * Pi * L[k]);
            worstSum = std::max(worstSum, e);
            meanSum += e;
            ++count;
            // Against the integral: the grid's error plus its discretisation.
            const double ei = std::abs(got[k] - L[k] * integral) / (4.0 * Pi * L[k]);
            worstIntegral = std::max(worstIntegral, ei);
            worstIntegralExcess = std::max(worstIntegralExcess, ei - (c.MaxPerCell + discretisation / (4.0 * Pi)));
          }
          // Alpha: the mean visibility over the sphere.
          EXPECT_NEAR(rgba[4 * ((size_t(z) * cells[1] + y) * cells[0] + x) + 3], sum / (4.0 * Pi), c.MaxPerCell + 1e-6);
        }
    meanSum /= double(count);
    std::printf("%s: |I - L sum| / (4 pi L): mean %.2e max %.2e; |I - L integral| / (4 pi L) max %.2e\n",
      c.Method == VisibilityGridParameters::Method::Sweep ? "sweep" : "brute force", meanSum, worstSum, worstIntegral);
    EXPECT_LT(worstSum, c.MaxPerCell);
    EXPECT_LT(meanSum, c.MeanPerCell);
    EXPECT_LE(worstIntegralExcess, 0.0);
  }
}

// Directions matter once the light does: a box of unequal sides under a low sun and a two-tone sky,
// against sum_n E_n exp(-sigma d(x, w_n)) with the brute-force grid (exact to 1e-4 per entry), so a
// light volume that paired a direction's visibility with another direction's light would fail.
TEST(LightVolume, HomogeneousBoxUnderASunIsTheAnalyticSum)
{
  const double sigma = 0.08;
  VisibilityScene scene({ { 33, 21, 15 } }, [](int, int, int) { return 1.0f; }, sigma);
  vs::EnvironmentMap map = vs::EnvironmentMap::SunDisk(64, glm::vec3(1.0f, 0.4f, 0.5f), 5.0,
    glm::vec3(400.0f, 300.0f, 200.0f), glm::vec3(0.0f));
  const vs::EnvironmentMap sky = vs::EnvironmentMap::TwoToneSky(64, glm::vec3(0.3f, 0.5f, 1.0f), glm::vec3(0.1f, 0.05f, 0.0f));
  for (size_t i = 0; i < map.Radiance.size(); ++i)
    map.Radiance[i] += sky.Radiance[i];
  map.Finalize();
  const vs::DeviceEnvironment env(scene.Context, map, 8);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.Algorithm = VisibilityGridParameters::Method::BruteForce;
  vs::VisibilityGrid grid(scene.Context);
  scene.Grid(grid, p);
  const uint32_t D = grid.Side();
  const std::vector<glm::vec3> e = vs::LightVolume::DirectionRadiance(env, D, 0.7);
  vs::LightVolume light(scene.Context);
  light.Update(grid, env, 0.7);
  const std::vector<float> rgba = light.Download();
  const auto cells = grid.Cells();
  double worst = 0.0, spread = 0.0;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (uint32_t z = 0; z < cells[2]; ++z)
    for (uint32_t y = 0; y < cells[1]; ++y)
      for (uint32_t x = 0; x < cells[0]; ++x)
      {
        const glm::dvec3 centre = CellCentre(grid, scene.Geometry, x, y, z);
        glm::dvec3 expected(0.0), bound(0.0);
        for (uint32_t n = 0; n < D * D; ++n)
        {
          const glm::dvec3 w(vs::SweepPlan::Direction(n, D));
          const double v = std::exp(-sigma * vstest::ExitDistance(centre, w, glm::dvec3(0.0), glm::dvec3(32.0, 20.0, 14.0)));
          expected += v * glm::dvec3(e[n]);
          bound += glm::dvec3(e[n]);
        }
        const glm::dvec3 got = Texel(rgba, grid, x, y, z);
        for (int k = 0; k < 3; ++k)
        {
          // The brute force's 1e-4 per entry, weighted by the light of each direction.
          worst = std::max(worst, std::abs(got[k] - expected[k]) / (1e-4 * bound[k]));
        }
        lo = glm::min(lo, got);
        hi = glm::max(hi, got);
      }
  spread = (hi.x - lo.x) / hi.x;
  std::printf("sun over a box: worst |I - sum| in units of 1e-4 sum E_n: %.2f; red varies by %.0f %% over the cells\n",
    worst, 100.0 * spread);
  EXPECT_LT(worst, 1.0);
  EXPECT_GT(spread, 0.3); // the sun is seen through very different depths: the test can tell directions apart
}

// No medium: V = 1 in every direction, so I = sum_n E_n = 4 pi L exactly (float rounding of D^2 terms);
// a two-tone sky gives 2 pi (upper + lower) (its horizon texels hold the exact mix).
TEST(LightVolume, EmptyVolumeGetsTheWholeSphere)
{
  VisibilityScene scene({ { 12, 9, 7 } }, [](int, int, int) { return 0.0f; }, 1.0);
  for (uint32_t D : { 4u, 8u, 16u })
  {
    VisibilityGridParameters p;
    p.DirectionResolution = D;
    vs::VisibilityGrid grid(scene.Context);
    scene.Grid(grid, p);
    vs::LightVolume light(scene.Context);
    const glm::dvec3 L(0.3, 1.7, 12.5);
    const vs::DeviceEnvironment constant(scene.Context, vs::EnvironmentMap::Constant(32, glm::vec3(L)), 8);
    light.Update(grid, constant, 1.0);
    std::vector<float> rgba = light.Download();
    ASSERT_FALSE(rgba.empty());
    for (size_t i = 0; i < rgba.size(); i += 4)
    {
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(rgba[i + k], 4.0 * Pi * L[k], 4.0 * Pi * L[k] * 4e-6) << "D " << D << " channel " << k;
      ASSERT_EQ(rgba[i + 3], 1.0f);
    }
    const glm::dvec3 upper(1.0, 0.8, 0.5), lower(0.1, 0.2, 0.05);
    const vs::DeviceEnvironment twoTone(
      scene.Context, vs::EnvironmentMap::TwoToneSky(64, glm::vec3(upper), glm::vec3(lower)), 8);
    light.Update(grid, twoTone, 1.0);
    rgba = light.Download();
    for (size_t i = 0; i < rgba.size(); i += 4)
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(rgba[i + k], 2.0 * Pi * (upper[k] + lower[k]), 2.0 * Pi * (upper[k] + lower[k]) * 4e-6);
  }
}

// E_n is the integral over texel n of the radiance the renderer looks up (EnvironmentMap::Evaluate: the
// texel holding the direction, as the render kernel's env_radiance), times the intensity: here that
// lookup supersampled over each grid texel (4 points inside every environment texel of it).
TEST(LightVolume, DirectionRadianceIntegratesTheRenderersLookup)
{
  auto f = [](glm::dvec3 d) {
    return glm::vec3(float(std::exp(6.0 * (d.x - 1.0))), float(0.1 + 0.1 * d.z), float(std::abs(d.y)));
  };
  auto ctx = vs::Context::Default();
  for (double rotation : { 0.0, 37.0 })
  {
    const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(MakeLatLong(256, 128, f), 64, rotation, 1.0, nullptr, 1);
    const vs::DeviceEnvironment env(ctx, map, 8);
    for (uint32_t D : { 4u, 8u, 16u })
    {
      const std::vector<glm::vec3> e = vs::LightVolume::DirectionRadiance(env, D, 2.5);
      ASSERT_EQ(e.size(), size_t(D) * D);
      const std::vector<float> importance = env.ImportanceLevel(int(std::log2(D) + 0.5));
      const int sub = 2 * map.Size / int(D); // 2 x 2 points per environment texel
      glm::dvec3 total(0.0);
      for (uint32_t n = 0; n < D * D; ++n)
      {
        glm::dvec3 mean(0.0);
        for (int b = 0; b < sub; ++b)
          for (int a = 0; a < sub; ++a)
          {
            const glm::vec2 uv((float(n % D) + (a + 0.5f) / sub) / float(D), (float(n / D) + (b + 0.5f) / sub) / float(D));
            mean += glm::dvec3(map.Evaluate(vs::shared::vs_octa_to_dir(uv))) / double(sub * sub);
          }
        const glm::dvec3 expected = 2.5 * (4.0 * Pi / (D * D)) * mean;
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(e[n][k], expected[k], 1e-5 * (expected[k] + 1e-3)) << "D " << D << " n " << n;
        // The luminance of the mean radiance is the importance the sampling uses.
        EXPECT_NEAR(vs::Luminance(e[n]) / (2.5 * 4.0 * Pi / (D * D)), importance[n], 1e-5 * (importance[n] + 1e-3));
        total += glm::dvec3(e[n]);
      }
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(total[k], 2.5 * 4.0 * Pi * map.MeanRadiance[k], 1e-5 * total[k]);
    }
  }
}

// Rebuilt exactly once per change of what it is made of (the grid's values, the environment, its
// intensity); a camera move changes none of them (the light volume takes no camera), so updating
// again as a frame after a camera move would does not rebuild.
TEST(LightVolume, RebuildsOnlyWhenTheGridOrTheEnvironmentChanges)
{
  VisibilityScene scene({ { 33, 33, 33 } }, [](int, int, int) { return 1.0f; }, 0.05);
  VisibilityGridParameters p;
  vs::VisibilityGrid grid(scene.Context);
  scene.Grid(grid, p);
  auto sky = [](glm::dvec3 d) { return glm::vec3(float(0.2 + std::max(0.0, d.x)), float(0.5 + 0.5 * d.z), 0.3f); };
  const vs::LatLongImage image = MakeLatLong(256, 128, sky);
  auto env0 = std::make_unique<vs::DeviceEnvironment>(
    scene.Context, vs::EnvironmentMap::FromLatLong(image, 32, 0.0, 1.0, nullptr, 1), 8);
  vs::LightVolume light(scene.Context);
  EXPECT_TRUE(light.Update(grid, *env0, 1.0));
  EXPECT_EQ(light.Builds(), 1u);
  const std::vector<float> before = light.Download();
  // Camera-only changes: the same grid, environment and intensity.
  for (int frame = 0; frame < 3; ++frame)
    EXPECT_FALSE(light.Update(grid, *env0, 1.0));
  EXPECT_EQ(light.Builds(), 1u);

  // The environment turned by 90 degrees about +Z: a new map, one rebuild, other values.
  auto env90 = std::make_unique<vs::DeviceEnvironment>(
    scene.Context, vs::EnvironmentMap::FromLatLong(image, 32, 90.0, 1.0, nullptr, 1), 8);
  EXPECT_TRUE(light.Update(grid, *env90, 1.0));
  EXPECT_FALSE(light.Update(grid, *env90, 1.0));
  EXPECT_EQ(light.Builds(), 2u);
  const std::vector<float> rotated = light.Download();
  double change = 0.0, scale = 0.0;
  for (size_t i = 0; i < before.size(); ++i)
  {
    change = std::max(change, double(std::abs(rotated[i] - before[i])));
    scale = std::max(scale, double(before[i]));
  }
  EXPECT_GT(change, 0.05 * scale);

  // The intensity: one rebuild, every value scaled (by 2 exactly: a power of two).
  EXPECT_TRUE(light.Update(grid, *env90, 2.0));
  EXPECT_EQ(light.Builds(), 3u);
  const std::vector<float> doubled = light.Download();
  for (size_t i = 0; i < doubled.size(); i += 4)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(doubled[i + k], 2.0f * rotated[i + k]);

  // New grid values: one rebuild.
  scene.Grid(grid, p);
  EXPECT_TRUE(light.Update(grid, *env90, 2.0));
  EXPECT_FALSE(light.Update(grid, *env90, 2.0));
  EXPECT_EQ(light.Builds(), 4u);
}

// A grid filling in reads redirected directions (VisibilityGrid::RedirectDirections): so does the light volume.
TEST(LightVolume, ReadsRedirectedDirections)
{
  VisibilityScene scene({ { 17, 17, 17 } }, [](int x, int, int) { return x < 8 ? 1.0f : 0.0f; }, 0.3);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  vs::VisibilityGrid grid(scene.Context);
  scene.Grid(grid, p);
  const vs::DeviceEnvironment env(scene.Context, vs::EnvironmentMap::Constant(8, glm::vec3(1.0f)), 8);
  const uint32_t DD = p.DirectionResolution * p.DirectionResolution;
  std::vector<std::pair<uint32_t, uint32_t>> redirects;
  for (uint32_t n = 1; n < DD; ++n)
    redirects.emplace_back(n, 0u); // every direction reads direction 0
  grid.RedirectDirections(redirects);
  const std::vector<float> v = grid.Download();
  vs::LightVolume light(scene.Context);
  light.Update(grid, env, 1.0);
  const std::vector<float> rgba = light.Download();
  for (size_t c = 0; c < rgba.size() / 4; ++c)
    ASSERT_NEAR(rgba[4 * c], 4.0 * Pi * v[c * DD], 1e-5 * 4.0 * Pi) << "cell " << c;
}

TEST(LightVolume, BadInputIsAnError)
{
  auto ctx = vs::Context::Default();
  const vs::DeviceEnvironment env(ctx, vs::EnvironmentMap::Constant(8, glm::vec3(1.0f)), 8);
  vs::LightVolume light(ctx);
  vs::VisibilityGrid empty(ctx);
  try
  {
    light.Update(empty, env, 1.0);
    FAIL() << "no error for a grid not computed";
  }
  catch (const vs::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("grid"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(light.Valid());
  EXPECT_TRUE(light.Download().empty());
  VisibilityScene scene({ { 9, 9, 9 } }, [](int, int, int) { return 1.0f; }, 0.1);
  VisibilityGridParameters p;
  p.DirectionResolution = 16;
  vs::VisibilityGrid grid(ctx);
  scene.Grid(grid, p);
  // An environment of 8 x 8 texels cannot give 16 x 16 directions their own radiance.
  EXPECT_THROW(light.Update(grid, env, 1.0), vs::InputError);
  EXPECT_THROW(light.Update(grid, env, std::nan("")), vs::InputError);
  EXPECT_THROW(light.Update(grid, env, -1.0), vs::InputError);
  EXPECT_THROW(light.Update(grid, env, 1e39), vs::InputError); // beyond the device's float
  EXPECT_THROW(vs::LightVolume::DirectionRadiance(env, 3, 1.0), vs::InputError);
  EXPECT_FALSE(light.Valid());
}
