// VTK's lights in the path kernel (issue 38: scene_lights.glsl, sampling/scene_lights.h): a directional
// light on a homogeneous slab against the single-scattering integral, a positional light's inverse-square
// falloff against its quadrature, two lights rendering the sum of each alone (per-pixel z-scores), a spot's
// cone, the lights' model on the CPU, and bad lights refused.
#include "vsRenderTestScene.h"
#include "vsError.h"
#include "vsSceneLightParams.h"
#include "vsSurfaceScattering.h"

#include "sampling/mc_params.h"
#include "sampling/scene_lights.h"
#include "sampling/strategies.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace vs::shared;
using vstest::RenderScene;

namespace
{
VsSceneLight Directional(glm::dvec3 travel, double intensity, glm::dvec3 color = glm::dvec3(1.0))
{
  VsSceneLight l;
  EXPECT_TRUE(vs::SceneLightParams::Make(l, false, -travel, glm::dvec3(0.0), intensity, color, 30.0, 1.0, glm::dvec3(1, 0, 0)));
  return l;
}

VsSceneLight Point(glm::dvec3 position, glm::dvec3 focal, double intensity, double cone = 180.0, double exponent = 1.0)
{
  VsSceneLight l;
  EXPECT_TRUE(vs::SceneLightParams::Make(l, true, position, focal, intensity, glm::dvec3(1.0), cone, exponent, glm::dvec3(0, 0, 1)));
  return l;
}

// The mean over pixels of channel 0 and its standard error.
std::pair<double, double> MeanOf(const std::vector<float>& mean, const std::vector<double>& var, double n)
{
  double m = 0.0, v = 0.0;
  const double pixels = double(mean.size() / 4);
  for (size_t i = 0; i < mean.size(); i += 4)
  {
    m += mean[i] / pixels;
    v += var[i] / n / (pixels * pixels);
  }
  return { m, std::sqrt(v) };
}
}

TEST(SceneLights, ModelOnTheCpu)
{
  // A directional light: its irradiance pi I c everywhere, towards where it comes from.
  const VsSceneLight d = Directional(glm::dvec3(0, 0, 1), 2.0, glm::dvec3(1.0, 0.5, 0.25));
  vec3 w;
  float distance;
  const vec3 E = vs_scene_light_incident(d, vec3(3.0f, -4.0f, 7.0f), w, distance);
  EXPECT_NEAR(E.x, 2.0 * M_PI, 1e-5);
  EXPECT_NEAR(E.z, 0.5 * M_PI, 1e-5);
  EXPECT_NEAR(w.z, -1.0f, 1e-6f);
  EXPECT_GT(distance, 1e29f);
  // A point light with attenuation (0, 0, 1): inverse square.
  const VsSceneLight p = Point(glm::dvec3(0, 0, 0), glm::dvec3(0, 0, 1), 1.0);
  const float e1 = vs_scene_light_incident(p, vec3(0, 0, 2), w, distance).x;
  const float e2 = vs_scene_light_incident(p, vec3(0, 0, 4), w, distance).x;
  EXPECT_NEAR(e1 / e2, 4.0f, 1e-4f);
  EXPECT_NEAR(distance, 4.0f, 1e-6f);
  EXPECT_NEAR(e1, M_PI / 4.0, 1e-5);
  // A spot of 30 degrees, exponent 2: cos^2 inside the cone, 0 outside.
  const VsSceneLight s = Point(glm::dvec3(0, 0, 0), glm::dvec3(0, 0, 1), 1.0, 30.0, 2.0);
  const float on = vs_scene_light_incident(s, vec3(0, 0, 1), w, distance).x;
  const float at20 = vs_scene_light_incident(s, vec3(std::sin(0.349066f), 0, std::cos(0.349066f)), w, distance).x;
  const float at40 = vs_scene_light_incident(s, vec3(std::sin(0.698132f), 0, std::cos(0.698132f)), w, distance).x;
  EXPECT_NEAR(at20 / on, std::pow(std::cos(0.349066), 2.0), 1e-4);
  EXPECT_EQ(at40, 0.0f);
  // VTK's default attenuation (1, 0, 0): no falloff.
  VsSceneLight flat = p;
  flat.attenuation = vec3(1.0f, 0.0f, 0.0f);
  EXPECT_EQ(vs_scene_light_incident(flat, vec3(0, 0, 2), w, distance).x,
    vs_scene_light_incident(flat, vec3(0, 0, 9), w, distance).x);
}

// A homogeneous slab of extinction sigma and albedo a, lit by a directional light of intensity I through
// its top face at cos(theta) = mu to the normal, no environment, one scattering event, seen along the
// normal: L = a (pi I) / (4 pi) (1 - exp(-sigma Z (1 + 1/mu))) / (sigma (1 + 1/mu)) sigma.
TEST(SceneLights, DirectionalLightOnASlab)
{
  const uint32_t nx = 40, nz = 5; // the slab z in [0, 4]; light enters within 4 tan(theta) of the centre
  const double sigma = 0.5, a = 0.8;
  RenderScene scene({ { nx, nx, nz } }, [](int, int, int) { return 1.0f; }, sigma, glm::vec3(float(a)),
    vs::EnvironmentMap::Constant(16, glm::vec3(0.0f)));
  for (double theta : { 0.0, 0.6 })
  {
    const double mu = std::cos(theta);
    auto p = scene.Params(4, 4, 18.5f, 20.5f, VS_STRATEGY_ENVIRONMENT, 2048, 3u, false);
    p.maxEvents = 1;
    p.lightCount = 1;
    p.lights[0] = Directional(glm::dvec3(std::sin(theta), 0.0, mu), 1.5);
    auto [mean, var] = scene.Render(p, 1);
    EXPECT_NE(scene.LastPipelineName.find("scene lights"), std::string::npos) << scene.LastPipelineName;
    const auto [m, se] = MeanOf(mean, var, scene.LastSamples);
    const double k = sigma * (1.0 + 1.0 / mu), Z = nz - 1.0;
    const double expected = a * M_PI * 1.5 / (4.0 * M_PI) * sigma * (1.0 - std::exp(-k * Z)) / k;
    EXPECT_LT(se, 0.01 * expected) << "too few samples to tell";
    EXPECT_NEAR(m, expected, 4.0 * se + 1e-3 * expected) << "theta " << theta;
  }
}

// A point light with inverse-square attenuation on the axis in front of a thin slab: the
// radiance of the pixels against the single-scattering quadrature at light distances D and 2D (about a
// factor 4 apart).
TEST(SceneLights, PositionalLightFallsOffAsTheInverseSquare)
{
  const uint32_t nx = 24, nz = 3; // slab z in [0, 2]
  const double sigma = 0.3, a = 1.0; // the quadrature has both transmittances exactly
  RenderScene scene({ { nx, nx, nz } }, [](int, int, int) { return 1.0f; }, sigma, glm::vec3(float(a)),
    vs::EnvironmentMap::Constant(16, glm::vec3(0.0f)));
  const double cx = 11.5, half = 0.25, Z = nz - 1.0;
  std::vector<double> measured, expectations;
  for (double D : { 6.0, 12.0 })
  {
    auto p = scene.Params(2, 2, float(cx - half), float(cx + half), VS_STRATEGY_ENVIRONMENT, 4096, 5u, false);
    p.maxEvents = 1;
    p.lightCount = 1;
    p.lights[0] = Point(glm::dvec3(cx, cx, -D), glm::dvec3(cx, cx, 0.0), 2.0);
    auto [mean, var] = scene.Render(p, 2);
    const auto [m, se] = MeanOf(mean, var, scene.LastSamples);
    // Quadrature over depth at the 4 pixel centres (offsets +-half/2): the camera's transmittance, the
    // isotropic phase, the light's irradiance pi I / r^2 and its transmittance over the slab.
    double expected = 0.0;
    for (double ox : { -0.5 * half, 0.5 * half })
      for (double oy : { -0.5 * half, 0.5 * half })
      {
        const int steps = 2000;
        for (int i = 0; i < steps; ++i)
        {
          const double t = (i + 0.5) * Z / steps;
          const double r = std::sqrt(ox * ox + oy * oy + (D + t) * (D + t));
          const double inside = t * r / (D + t);
          expected += std::exp(-sigma * t) * sigma * a / (4.0 * M_PI) * M_PI * 2.0 / (r * r) *
            std::exp(-sigma * inside) * Z / steps / 4.0;
        }
      }
    EXPECT_LT(se, 0.02 * expected);
    EXPECT_NEAR(m, expected, 4.0 * se + 1e-3 * expected) << "light at " << D;
    measured.push_back(m);
    expectations.push_back(expected);
  }
  // Twice as far, about a quarter of the light (not exactly: the slab's depth adds to both distances).
  EXPECT_GT(expectations[0] / expectations[1], 3.3);
  EXPECT_NEAR(measured[0] / measured[1], expectations[0] / expectations[1], 0.05 * expectations[0] / expectations[1]);
}

// Linearity: two lights (a coloured directional one and a spot) on the heterogeneous phantom with an
// environment render the sum of each alone and the environment alone: per-pixel z-scores, multiple
// scattering, with and without the surface lobe.
TEST(SceneLights, TwoLightsAreTheSumOfEachAlone)
{
  auto phantom = [](int x, int y, int z) {
    const float r = glm::length(glm::vec3(x, y, z) - glm::vec3(11.5f));
    return std::max(0.0f, 1.0f - r / 10.0f);
  };
  RenderScene scene({ { 24, 24, 24 } }, phantom, 1.0, glm::vec3(0.9f, 0.8f, 0.7f),
    vs::EnvironmentMap::Constant(16, glm::vec3(0.2f)));
  const VsSceneLight A = Directional(glm::normalize(glm::dvec3(1.0, -0.5, 1.0)), 1.0, glm::dvec3(1.0, 0.6, 0.3));
  const VsSceneLight B = Point(glm::dvec3(11.5, 11.5, -10.0), glm::dvec3(11.5, 11.5, 11.5), 200.0, 20.0, 3.0);
  for (bool surface : { false, true })
  {
    auto base = scene.Params(8, 8, -1.0f, 24.0f, VS_STRATEGY_ENVIRONMENT, 512, 13u, false);
    base.maxEvents = 16;
    if (surface)
    {
      vs::SurfaceScattering::Settings s;
      s.Shade = true;
      s.Diffuse = 0.7;
      s.Specular = 0.3;
      vs::SurfaceScattering::Set(base, s, 1.0, 1.0, 1.0, 1.0);
    }
    std::vector<std::vector<float>> means;
    std::vector<std::vector<double>> vars;
    uint32_t seed = 100;
    for (int which = 0; which < 4; ++which) // both; A alone; B alone; the environment alone
    {
      auto p = base;
      p.camera.seed = seed++;
      if (which == 0)
      {
        p.lightCount = 2;
        p.lights[0] = A;
        p.lights[1] = B;
      }
      else if (which < 3)
      {
        p.lightCount = 1;
        p.lights[0] = which == 1 ? A : B;
        p.environmentIntensity = 0.0f;
      }
      auto [m, v] = scene.Render(p, 2);
      means.push_back(m);
      vars.push_back(v);
    }
    const double n = scene.LastSamples;
    double chi2 = 0.0;
    int dof = 0;
    double lightA = 0.0, lightB = 0.0;
    for (size_t i = 0; i < means[0].size(); ++i)
    {
      if (i % 4 == 3)
        continue;
      const double sum = means[1][i] + means[2][i] + means[3][i];
      const double se2 = (vars[0][i] + vars[1][i] + vars[2][i] + vars[3][i]) / n;
      lightA += means[1][i];
      lightB += means[2][i];
      if (se2 > 0.0)
      {
        chi2 += (means[0][i] - sum) * (means[0][i] - sum) / se2;
        ++dof;
      }
    }
    EXPECT_GT(dof, 100);
    EXPECT_LT(chi2, dof + 4.0 * std::sqrt(2.0 * dof) + 20.0) << (surface ? "with" : "without") << " the surface lobe";
    EXPECT_GT(lightA, 1.0) << "the directional light lights the phantom";
    EXPECT_GT(lightB, 1.0) << "the spot lights the phantom";
  }
}

// Bad lights: an error naming the light; nothing rendered.
TEST(SceneLights, BadLightsAreErrors)
{
  RenderScene scene({ { 8, 8, 8 } }, [](int, int, int) { return 0.5f; }, 1.0, glm::vec3(0.9f),
    vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  auto expectError = [&](const vs::shared::VsMonteCarloParams& p, const std::string& words) {
    vstest::ExpectInputError(scene, p, words);
  };
  auto p = scene.Params(4, 4, 0.0f, 7.0f, VS_STRATEGY_ENVIRONMENT, 4, 1u);
  p.lightCount = VS_MAX_SCENE_LIGHTS + 1;
  expectError(p, "at most 8 lights");
  p.lightCount = 1;
  p.lights[0] = Directional(glm::dvec3(0, 0, 1), 1.0);
  p.lights[0].irradiance.y = NAN;
  expectError(p, "light 0");
  p.lights[0] = Directional(glm::dvec3(0, 0, 1), 1.0);
  p.lights[0].kind = 7u;
  expectError(p, "light 0: unknown kind 7");
  VsSceneLight l;
  EXPECT_FALSE(vs::SceneLightParams::Make(l, false, glm::dvec3(1.0), glm::dvec3(1.0), 1.0, glm::dvec3(1.0), 30.0, 1.0,
    glm::dvec3(1, 0, 0)))
    << "a directional light needs a direction";
}
