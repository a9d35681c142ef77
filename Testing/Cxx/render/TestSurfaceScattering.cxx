// Hybrid scattering on the device (issue 38: surface_scattering.glsl in the path kernel): the white furnace
// with the surface lobe, the estimators (light sampling alone, the mixture's sampling alone, both by the
// power and the balance heuristic, a grid strategy) agreeing with the lobe on, blending 2 rendering the
// volumetric image bit for bit, a lobe that never fires agreeing with the volumetric image, the lobe
// changing the image, and bad settings refused.
#include "vsRenderTestScene.h"
#include "vsError.h"
#include "vsSurfaceScattering.h"

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
// The surface fields as the mapper sets them for the phantom (scalars in [0, 1], spacing 1, unit distance 1).
void SetSurface(VsMonteCarloParams& p, double blending, double diffuse, double specular, double power)
{
  vs::SurfaceScattering::Settings s;
  s.Shade = true;
  s.Blending = blending;
  s.Diffuse = diffuse;
  s.Specular = specular;
  s.SpecularPower = power;
  vs::SurfaceScattering::Set(p, s, 1.0, 1.0, 1.0, 1.0);
}

}

// Albedo 1 under a constant sky of radiance 1, with a Lambert surface lobe of albedo 1 (Diffuse 1,
// Specular 0) wherever the gradient allows (blending 0) and blended (blending 1), with an isotropic and a
// forward phase: radiance 1 everywhere, for Environment sampling and TwoStep.
TEST(SurfaceScattering, WhiteFurnace)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 1.2, glm::vec3(1.0f), vs::EnvironmentMap::Constant(32, glm::vec3(1.0f)));
  struct Case
  {
    double blending;
    float g;
    uint32_t strategy;
  };
  for (const Case& c : { Case{ 0.0, 0.0f, VS_STRATEGY_ENVIRONMENT }, Case{ 1.0, 0.6f, VS_STRATEGY_ENVIRONMENT },
         Case{ 0.0, 0.3f, VS_STRATEGY_TWO_STEP } })
  {
    auto p = scene.Params(8, 8, -1.0f, 24.0f, c.strategy, 1024, 5u, true);
    p.maxEvents = VS_MAX_SCATTERING_EVENTS;
    p.anisotropy = c.g;
    SetSurface(p, c.blending, 1.0, 0.0, 10.0);
    auto [mean, var] = scene.Render(p, 2);
    EXPECT_NE(scene.LastPipelineName.find("surface scattering"), std::string::npos) << scene.LastPipelineName;
    const Against r = AgainstConstant(mean, var, scene.LastSamples, 1.0);
    EXPECT_LT(r.chi2, r.Bound()) << "blending " << c.blending << " g " << c.g << " (largest error " << r.maxError
                                 << ")";
    EXPECT_GT(r.dof, 100);
  }
}

// With a specular part the lobe loses the light its microfacets would reflect more than once (a
// single-scattering GGX lobe): never brighter than the furnace, and not much darker at this roughness.
TEST(SurfaceScattering, FurnaceWithSpecularIsAtMostOne)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 1.2, glm::vec3(1.0f), vs::EnvironmentMap::Constant(32, glm::vec3(1.0f)));
  auto p = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_ENVIRONMENT, 512, 6u, false);
  p.maxEvents = VS_MAX_SCATTERING_EVENTS;
  SetSurface(p, 0.0, 0.5, 0.5, 30.0);
  auto [mean, var] = scene.Render(p, 2);
  double sum = 0.0, alpha = 0.0, se2 = 0.0;
  for (size_t i = 0; i < mean.size(); i += 4)
  {
    sum += mean[i];
    alpha += mean[i + 3];
    se2 += var[i] / scene.LastSamples;
  }
  const double m = sum / alpha, se = std::sqrt(se2) / alpha;
  EXPECT_LT(m, 1.0 + 4.0 * se) << "the lobe creates no energy";
  EXPECT_GT(m, 0.6) << "the lobe loses only the microfacets' multiple scattering (compounded over the many events of an albedo-1 medium: 0.79 measured)";
}

// Light sampling alone, the mixture's sampling alone and both (power, balance), and TwoStep agree pixel
// by pixel with the surface lobe on (coloured albedo, a specular part, under a sun with sky): the kernel
// next-event estimation evaluates is the one the continuation samples, and its density is the one MIS uses.
TEST(SurfaceScattering, EstimatorsAgree)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 0.8, glm::vec3(0.95f, 0.8f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1.0f, 0.5f, -1.0f)), 20.0, glm::vec3(8.0f),
      glm::vec3(0.3f, 0.4f, 0.6f)));
  auto base = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_ENVIRONMENT, 1024, 21u, false);
  base.maxEvents = 64;
  base.anisotropy = 0.3f;
  SetSurface(base, 0.5, 0.6, 0.4, 20.0);
  auto [refMean, refVar] = scene.Render(base, 2);
  const double n = scene.LastSamples;
  struct Variant
  {
    const char* name;
    uint32_t strategy, mis;
  };
  const Variant variants[] = { { "light sampling alone", VS_STRATEGY_ENVIRONMENT, VS_MIS_LIGHT_ONLY },
    { "the mixture's sampling alone", VS_STRATEGY_ENVIRONMENT, VS_MIS_PHASE_ONLY },
    { "balance heuristic", VS_STRATEGY_ENVIRONMENT, VS_MIS_BALANCE }, { "TwoStep", VS_STRATEGY_TWO_STEP, VS_MIS_POWER } };
  for (const Variant& v : variants)
  {
    auto p = base;
    p.strategy = v.strategy;
    p.mis = v.mis;
    p.camera.seed = 77u;
    auto [mean, var] = scene.Render(p, 2);
    const auto r = vstest::Compare(refMean, refVar, mean, var, n);
    EXPECT_LT(r.chi2, r.Bound()) << v.name << " against Environment sampling with MIS";
    EXPECT_GT(r.dof, 100);
  }
}

// Blending 2 (volumetric only) renders the volumetric kernel's image bit for bit (the surface pipeline is
// not even made); a surface pipeline whose lobe never fires (no gradient scale: P_s = 0) agrees with it
// statistically; the lobe at blending 0 changes the image far beyond the noise.
TEST(SurfaceScattering, BlendingTwoIsVolumetric)
{
  RenderScene scene({ { 24, 24, 24 } }, Phantom, 1.0, glm::vec3(0.9f, 0.7f, 0.5f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, -1, 1)), 8.0, glm::vec3(30.0f), glm::vec3(0.3f)));
  auto p = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_ENVIRONMENT, 256, 4u, true);
  p.maxEvents = 16;
  auto [volumetric, vv] = scene.Render(p, 1);
  EXPECT_EQ(scene.LastPipelineName.find("surface"), std::string::npos);
  auto q = p;
  SetSurface(q, 2.0, 0.7, 0.3, 10.0);
  auto [two, v2] = scene.Render(q, 1);
  EXPECT_EQ(scene.LastPipelineName.find("surface"), std::string::npos) << scene.LastPipelineName;
  EXPECT_EQ(two, volumetric) << "blending 2 is the volumetric image, bit for bit";
  EXPECT_EQ(v2, vv);

  auto never = p;
  SetSurface(never, 0.0, 0.7, 0.3, 10.0);
  never.gradientScale = 0.0f;
  never.camera.seed = 9u;
  auto [nm, nv] = scene.Render(never, 1);
  EXPECT_NE(scene.LastPipelineName.find("surface scattering"), std::string::npos) << scene.LastPipelineName;
  const auto same = vstest::Compare(volumetric, vv, nm, nv, scene.LastSamples);
  EXPECT_LT(same.chi2, same.Bound()) << "a lobe that never fires is the volumetric estimate";
  EXPECT_GT(same.dof, 100);

  auto on = p;
  SetSurface(on, 0.0, 0.7, 0.3, 10.0);
  on.camera.seed = 9u;
  auto [sm, sv] = scene.Render(on, 1);
  const auto differs = vstest::Compare(volumetric, vv, sm, sv, scene.LastSamples);
  EXPECT_GT(differs.chi2, 2.0 * differs.Bound()) << "the surface lobe changes the image (twice the bound: p far below 1e-9)";
}

// Bad settings: an error naming the setting, the value and the range; nothing rendered.
TEST(SurfaceScattering, BadSettingsAreErrors)
{
  RenderScene scene({ { 8, 8, 8 } }, [](int, int, int) { return 0.5f; }, 1.0, glm::vec3(0.9f),
    vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  auto expectError = [&](const vs::shared::VsMonteCarloParams& p, const std::string& words) {
    vstest::ExpectInputError(scene, p, words);
  };
  auto p = scene.Params(4, 4, 0.0f, 7.0f, VS_STRATEGY_ENVIRONMENT, 4, 1u);
  SetSurface(p, 0.0, 1.0, 0.0, 10.0);
  for (float b : { -0.1f, 2.5f, std::nanf("") })
  {
    auto q = p;
    q.surfaceBlending = b;
    expectError(q, "volumetric scattering blending must be in [0, 2]");
  }
  auto q = p;
  q.surfaceRoughness = 0.0f;
  expectError(q, "roughness must be in (0, 1]");
  q = p;
  q.surfaceDiffuse = 0.8f;
  q.surfaceSpecular = 0.8f;
  expectError(q, "diffuse plus specular weight must be at most 1");
}
