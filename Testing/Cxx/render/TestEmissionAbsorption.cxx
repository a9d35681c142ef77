// Emission-absorption on the device against the analytic homogeneous cube:
// alpha = 1 - exp(-sigma_t L), colour = c * alpha, for every ray through the cube.
#include "vsOrthoCamera.h"
#include "vsVisibilityTestScene.h"
#include "vsMajorantGrid.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsEmissionAbsorptionPass.h"
#include "vsTransferFunctionTable.h"
#include "vsError.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace vs;

namespace
{
// An orthographic view along +z (vstest::OrthoAlongZ) of an n^3 volume in world = index space (its box from
// voxel 0 to n - 1) through `tf`, marched at `step`; rays end at opacity 0.999.
shared::VsEmissionAbsorptionParams OrthoAlongZ(uint32_t w, uint32_t h, float lo, float hi, float z0, float z1,
  uint32_t n, const TransferFunctionTable& tf, float step)
{
  shared::VsEmissionAbsorptionParams p{};
  p.camera = vstest::OrthoAlongZ(w, h, lo, hi, z0, z1);
  p.volume.worldToIndex = glm::mat4(1.0f);
  p.volume.boxMin = glm::vec3(0.0f);
  p.volume.boxMax = glm::vec3(float(n - 1));
  p.volume.dims = glm::vec3(float(n));
  p.volume.tf = tf.Params();
  p.step = step;
  p.terminationOpacity = 0.999f;
  return p;
}
}

TEST(EmissionAbsorption, HomogeneousCubeIsAnalytic)
{
  auto ctx = Context::Default();
  const uint32_t n = 16;
  std::vector<float> voxels(n * n * n, 100.0f);
  DeviceVolume volume(ctx, voxels.data(), { { n, n, n } });
  const double alpha = 0.1, unit = 1.0;
  const double color[3] = { 0.9, 0.5, 0.2 };
  auto samples = TransferFunctionSamples::FromFunctions(0.0f, 255.0f, 256, [&](double) { return alpha; },
    [&](double, double c[3]) {
      for (int i = 0; i < 3; ++i)
        c[i] = color[i];
    },
    unit, 1.0);
  TransferFunctionTable tf(ctx, samples);

  const uint32_t W = 32, H = 32;
  auto p = OrthoAlongZ(W, H, -4.0f, 19.0f, -10.0f, 30.0f, n, tf, 0.37f); // a step that does not divide L

  EmissionAbsorptionPass pass(ctx);
  std::vector<float> rgba = pass.Render(volume, tf, nullptr, p, {});
  const double sigma = -std::log(1.0 - alpha) / unit;
  const double expectedAlpha = 1.0 - std::exp(-sigma * (n - 1));
  int inside = 0;
  for (uint32_t y = 0; y < H; ++y)
  {
    for (uint32_t x = 0; x < W; ++x)
    {
      float wx = -4.0f + 23.0f * (x + 0.5f) / W, wy = -4.0f + 23.0f * (y + 0.5f) / H;
      const float* px = &rgba[4 * (y * W + x)];
      if (wx > 0.1f && wx < n - 1.1f && wy > 0.1f && wy < n - 1.1f)
      {
        ++inside;
        EXPECT_NEAR(px[3], expectedAlpha, 0.01 * expectedAlpha) << x << "," << y;
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_NEAR(px[c], color[c] * expectedAlpha, 0.01 * color[c] * expectedAlpha);
        }
      }
      else if (wx < -0.1f || wx > n - 0.9f || wy < -0.1f || wy > n - 0.9f)
      {
        EXPECT_EQ(px[3], 0.0f) << "ray outside the cube at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(inside, 300);
}

// Empty-space skipping (the majorant grid's empty bricks) changes where the march samples, not what
// it integrates: a cube of 16 voxels in the middle of a 48^3 volume of empty bricks and a slab one
// voxel thick in a brick of its own, against the analytic optical depths, with and without the
// majorants. sigma_t(s) = 0.1 s; under trilinear interpolation a ramp of one voxel at each face adds
// half a voxel, so a ray along z through the cube crosses an optical depth of 0.1 x 16 and the slab
// (its tent of one voxel) 0.1 x 1. A skipped non-empty brick would lose the slab or part of the cube.
TEST(EmissionAbsorption, EmptySpaceSkippingKeepsTheImage)
{
  const int n = 48;
  vstest::VisibilityScene scene({ { n, n, n } },
    [](int x, int y, int z) {
      const bool cube = x >= 16 && x <= 31 && y >= 16 && y <= 31 && z >= 16 && z <= 31;
      return cube || z == 42 ? 1.0f : 0.0f;
    },
    0.1);
  const uint32_t W = 48, H = 48;
  auto p = OrthoAlongZ(W, H, 0.0f, float(n - 1), -10.0f, 80.0f, n, *scene.TF, 0.37f);
  ASSERT_GT(scene.Majorants->MaxMajorant(), 0.0f);
  EmissionAbsorptionPass pass(scene.Context);
  const std::vector<float> skipped = pass.Render(*scene.Volume, *scene.TF, scene.Majorants.get(), p, {});
  const std::vector<float> marched = pass.Render(*scene.Volume, *scene.TF, nullptr, p, {});
  int cube = 0, slab = 0;
  for (uint32_t y = 0; y < H; ++y)
  {
    for (uint32_t x = 0; x < W; ++x)
    {
      const float wx = float(n - 1) * (x + 0.5f) / W, wy = float(n - 1) * (y + 0.5f) / H;
      const bool inCube = wx > 16.5f && wx < 30.5f && wy > 16.5f && wy < 30.5f;
      const bool outside = wx < 14.5f || wx > 32.5f || wy < 14.5f || wy > 32.5f;
      if (!inCube && !outside)
      {
        continue; // the cube's rim, between the two
      }
      const double expected = 1.0 - std::exp(-0.1 * (inCube ? 17.0 : 1.0));
      const size_t i = 4 * (size_t(y) * W + x);
      // The march's quadrature of the ramps (steps of 0.37 at a random offset) errs by up to ~3% on
      // the slab; a skipped brick of it would lose all of it.
      EXPECT_NEAR(skipped[i + 3], expected, 0.05 * expected) << x << "," << y;
      EXPECT_NEAR(marched[i + 3], expected, 0.05 * expected) << x << "," << y;
      EXPECT_NEAR(skipped[i], skipped[i + 3], 1e-5); // white: colour = alpha
      (inCube ? cube : slab)++;
    }
  }
  EXPECT_GT(cube, 100);
  EXPECT_GT(slab, 1000);
}

TEST(EmissionAbsorption, OpaqueDepthStopsRays)
{
  auto ctx = Context::Default();
  const uint32_t n = 8;
  std::vector<float> voxels(n * n * n, 1.0f);
  DeviceVolume volume(ctx, voxels.data(), { { n, n, n } });
  TransferFunctionTable tf(ctx, TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 16,
    [](double) { return 0.5; }, [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0, 1.0));
  const uint32_t W = 8, H = 8;
  auto p = OrthoAlongZ(W, H, 1.0f, 6.0f, -10.0f, 30.0f, n, tf, 0.25f);
  // Opaque surface at world z = 2 (window depth = (z - z0) / (z1 - z0) for this linear projection).
  std::vector<float> depth(W * H, float((2.0 + 10.0) / 40.0));
  EmissionAbsorptionPass pass(ctx);
  auto rgba = pass.Render(volume, tf, nullptr, p, depth);
  const double expected = 1.0 - std::exp(std::log(0.5) * 2.0);
  for (uint32_t i = 0; i < W * H; ++i)
  {
    EXPECT_NEAR(rgba[4 * i + 3], expected, 1e-3);
  }
}

TEST(EmissionAbsorption, NonFiniteVoxelsAreEmptyAndCounted)
{
  auto ctx = Context::Default();
  std::vector<float> voxels(4 * 4 * 4, 1.0f);
  voxels[5] = std::nanf("");
  voxels[6] = INFINITY;
  voxels[7] = -INFINITY;
  DeviceVolume volume(ctx, voxels.data(), { { 4, 4, 4 } });
  EXPECT_EQ(volume.NonFiniteCount(), 3u);
  EXPECT_EQ(volume.Range()[0], 1.0f);
  EXPECT_EQ(volume.Range()[1], 1.0f);
}

// The emission-absorption mode's Phong shading with VTK's lights (issue 38): a ball whose gradient gives
// every sample a normal, shaded
//   - with one directional light of intensity 1 along the view (E = pi: radiance 1 towards the sample), as
//     with the built-in headlight (lightCount 0): the same image to float precision;
//   - with the light from the side: another image (the lights change the shading), and with two lights
//     the sum of each alone less one ambient term;
//   - without shading, the lights change nothing: the same image bit for bit.
TEST(EmissionAbsorption, ShadingFollowsVtkLights)
{
  auto ctx = Context::Default();
  const uint32_t n = 24;
  std::vector<float> voxels(n * n * n);
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x)
      {
        const float r = std::sqrt(float((x - 11.5) * (x - 11.5) + (y - 11.5) * (y - 11.5) + (z - 11.5) * (z - 11.5)));
        voxels[(z * n + y) * n + x] = std::max(0.0f, 1.0f - r / 10.0f);
      }
  DeviceVolume volume(ctx, voxels.data(), { { n, n, n } });
  auto samples = TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 256, [&](double s) { return 0.3 * s; },
    [&](double, double c[3]) { c[0] = 0.9, c[1] = 0.6, c[2] = 0.3; }, 1.0, 1.0);
  TransferFunctionTable tf(ctx, samples);
  const uint32_t W = 24, H = 24;
  auto p = OrthoAlongZ(W, H, 0.0f, 23.0f, -10.0f, 40.0f, n, tf, 0.5f);
  p.ambient = 0.1f;
  p.diffuse = 0.7f;
  p.specular = 0.3f;
  p.specularPower = 20.0f;
  p.lightDirection = glm::vec3(0.0f, 0.0f, -1.0f); // towards the light: against the view (+z)
  p.lightIntensity = 1.0f;
  const auto light = [](glm::vec3 travel) {
    shared::VsSceneLight l{};
    l.kind = shared::VS_LIGHT_DIRECTIONAL;
    l.direction = glm::normalize(travel);
    l.cosCone = -2.0f;
    l.irradiance = glm::vec3(3.14159265f);
    l.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
    return l;
  };
  EmissionAbsorptionPass pass(ctx);
  const std::vector<float> headlight = pass.Render(volume, tf, nullptr, p, {}, true);
  p.lightCount = 1;
  p.lights[0] = light(glm::vec3(0.0f, 0.0f, 1.0f));
  const std::vector<float> along = pass.Render(volume, tf, nullptr, p, {}, true);
  double worst = 0.0, sum = 0.0;
  for (size_t i = 0; i < along.size(); ++i)
  {
    worst = std::max(worst, double(std::abs(along[i] - headlight[i])));
    sum += headlight[i];
  }
  EXPECT_GT(sum, 10.0);
  EXPECT_LT(worst, 1e-5) << "a light along the view is the headlight";
  p.lights[0] = light(glm::vec3(1.0f, 0.0f, 0.2f));
  const std::vector<float> side = pass.Render(volume, tf, nullptr, p, {}, true);
  double change = 0.0;
  for (size_t i = 0; i < side.size(); ++i)
    change = std::max(change, double(std::abs(side[i] - headlight[i])));
  EXPECT_GT(change, 0.05) << "a light from the side shades otherwise";
  // Two lights: the sum of each alone less the ambient term counted twice (ambient x albedo, composited).
  p.lightCount = 2;
  p.lights[1] = light(glm::vec3(0.0f, 0.0f, 1.0f));
  const std::vector<float> both = pass.Render(volume, tf, nullptr, p, {}, true);
  p.lightCount = 0;
  p.diffuse = 0.0f;
  p.specular = 0.0f;
  const std::vector<float> ambient = pass.Render(volume, tf, nullptr, p, {}, true);
  for (size_t i = 0; i < both.size(); ++i)
    if (i % 4 != 3)
      EXPECT_NEAR(both[i], side[i] + along[i] - ambient[i], 1e-4) << i;
  // Shading off: the lights are not read.
  p.lightCount = 0;
  const std::vector<float> unlit = pass.Render(volume, tf, nullptr, p, {}, false);
  p.lightCount = 2;
  const std::vector<float> unlitWithLights = pass.Render(volume, tf, nullptr, p, {}, false);
  EXPECT_EQ(0, std::memcmp(unlit.data(), unlitWithLights.data(), unlit.size() * sizeof(float)));
  p.lightCount = 9;
  EXPECT_THROW(pass.Render(volume, tf, nullptr, p, {}, true), InputError);
}
