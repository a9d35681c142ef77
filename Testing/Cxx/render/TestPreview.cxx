// The emission-absorption pass's lit modes (ea_render.comp, VS_EA_LIGHTING_*): the preview's single
// scattering from the light volume against the 1D quadrature of a homogeneous box's single scattering
// under a constant sky (the light volume's analytic values, as TestLightVolume has them); the preview
// is deterministic (no jitter, no random stream); ambient occlusion is the preview under a white sky.
#include "vsHalfSpace.h"
#include "vsOrthoCamera.h"
#include "vsVisibilityTestScene.h"

#include "vsDeviceEnvironment.h"
#include "vsEmissionAbsorptionPass.h"
#include "vsEnvironmentMap.h"
#include "vsError.h"
#include "vsLightVolume.h"
#include "vsSweepPlan.h"
#include "vsVolumeParams.h"
#include "sampling/display_transform.h"
#include "sampling/dither.h"
#include "sampling/interpolation.h"
#include "sampling/octahedral.h"
#include "sampling/phase_moments.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

using vstest::VisibilityScene;

namespace
{
const double Pi = 3.14159265358979323846;
const double Sigma = 0.05;          // extinction per voxel of the box (world = index)
const uint32_t Voxels = 33;         // box [0, 32]^3
const double Edge = Voxels - 1.0;

// The light volume's analytic value per unit sky radiance: sum_n (4 pi / D^2) exp(-sigma d(x, w_n)).
double AnalyticLight(glm::dvec3 x, uint32_t D)
{
  double sum = 0.0;
  for (uint32_t n = 0; n < D * D; ++n)
  {
    sum += 4.0 * Pi / (D * D) *
      std::exp(-Sigma * vstest::ExitDistance(x, glm::dvec3(vs::SweepPlan::Direction(n, D)), glm::dvec3(0.0), glm::dvec3(Edge)));
  }
  return sum;
}

// The downloaded light volume (channel k) trilinear between cell centres, clamped: the shader's light_at.
double InterpolatedLight(const std::vector<float>& rgba, const vs::VisibilityGrid& grid, glm::dvec3 x, int k)
{
  const auto c = grid.Cells();
  const glm::dvec3 cs(grid.CellSize());
  double f[3];
  uint32_t i0[3], i1[3];
  for (int a = 0; a < 3; ++a)
  {
    const double g = std::clamp(x[a] / cs[a] - 0.5, 0.0, double(c[a] - 1));
    i0[a] = std::min(uint32_t(std::floor(g)), c[a] - 1);
    i1[a] = std::min(i0[a] + 1, c[a] - 1);
    f[a] = g - i0[a];
  }
  double v = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const uint32_t ix = corner & 1 ? i1[0] : i0[0], iy = corner & 2 ? i1[1] : i0[1], iz = corner & 4 ? i1[2] : i0[2];
    const double w = (corner & 1 ? f[0] : 1 - f[0]) * (corner & 2 ? f[1] : 1 - f[1]) * (corner & 4 ? f[2] : 1 - f[2]);
    v += w * rgba[4 * ((size_t(iz) * c[1] + iy) * c[0] + ix) + k];
  }
  return v;
}

struct LitBox
{
  VisibilityScene Scene;
  vs::VisibilityGrid Grid{ Scene.Context };
  vs::LightVolume Light{ Scene.Context };
  std::unique_ptr<vs::DeviceEnvironment> Env;
  vs::shared::VsEmissionAbsorptionParams Params{};
  static constexpr uint32_t W = 17, H = 17;
  static constexpr float Lo = -2.0f, Hi = 34.0f; // pixel (8, 8) looks through the box's centre

  explicit LitBox(glm::vec3 sky, const std::function<float(int, int, int)>& scalar = [](int, int, int) { return 1.0f; })
    : Scene({ { Voxels, Voxels, Voxels } }, scalar, Sigma)
  {
    this->Env = std::make_unique<vs::DeviceEnvironment>(Scene.Context, vs::EnvironmentMap::Constant(16, sky), 8);
    vs::VisibilityGridParameters g;
    g.StorageFormat = vs::VisibilityGridParameters::Format::Float32;
    g.Filtering = false;
    g.Algorithm = vs::VisibilityGridParameters::Method::BruteForce; // V exact to 1e-4 (TestVisibilityGrid)
    Scene.Grid(this->Grid, g);
    this->Light.Update(this->Grid, *this->Env, 1.0);
    this->Params.camera = vstest::OrthoAlongZ(W, H, Lo, Hi, -10.0f, 40.0f);
    this->Params.volume = vs::MakeVolumeParams(Scene.Geometry, *Scene.TF, vs::shared::VS_INTERPOLATION_LINEAR, {});
    this->Params.step = 0.25f;
    this->Params.terminationOpacity = 0.995f;
    const auto c = this->Grid.Cells();
    this->Params.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    this->Params.grid.cellSize = this->Grid.CellSize();
    this->Params.grid.side = this->Grid.Side();
    this->Params.lightIntensity = 1.0f;
  }

  std::vector<float> Render(uint32_t lighting)
  {
    vs::EmissionAbsorptionPass pass(Scene.Context);
    return pass.Render(*Scene.Volume, *Scene.TF, nullptr, this->Params, {}, false, lighting, &this->Light.Image());
  }

  static double PixelCentre(uint32_t i) { return Lo + (Hi - Lo) * (i + 0.5) / W; }
};
}

// The preview of a homogeneous box (sigma 0.05 per voxel, 32 voxels deep, white albedo) under a
// constant sky L, along rays parallel to z through the box: the pass's L_pix against
//   (a) the same discrete sum on the host (steps of 0.25, each sampled at the pixel's fixed offset
//       j of dither.h, the downloaded light volume trilinear): the shader's arithmetic, to float
//       precision (relative 1e-3);
//   (b) the single scattering's 1D quadrature, L_k int_0^32 e^{-sigma s} sigma (1 / 4 pi) I(x_s) ds
//       with the light volume's analytic I (TestLightVolume), 3200 midpoint steps. The preview is
//       biased by the trilinear interpolation of I between cell centres: L_pix is a positive weighted
//       integral of I, so its relative error is at most the largest relative error of the
//       interpolated I along the ray, measured here per ray, plus the grid's (brute force: 1e-4 of
//       4 pi L) and the step's: each step's weight e^{-sigma s} sigma ds is exact, its I read at
//       offset j instead of integrated, which errs by (j - 1/2) dt I' dt to first order, so in all by
//       at most |j - 1/2| dt max |I' / I| relative (I' measured along the ray), plus 1e-4 for the
//       second order. That bound is the tolerance (it is some 1-3% at the rays near the box's faces,
//       where I bends most).
// Dropping the 1 / (4 pi) fails both by a factor 12.6; a wrong cell-centre offset fails (a).
TEST(Preview, HomogeneousBoxMatchesSingleScatteringQuadrature)
{
  const glm::dvec3 L(0.5, 1.0, 2.0);
  LitBox box{ glm::vec3(L) };
  const std::vector<float> rgba = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  ASSERT_EQ(rgba.size(), 4u * LitBox::W * LitBox::H);
  const std::vector<float> light = box.Light.Download();
  const uint32_t D = box.Grid.Side();
  const double expectedAlpha = 1.0 - std::exp(-Sigma * Edge);
  int rays = 0;
  double worstA = 0.0, worstB = 0.0, worstBound = 0.0;
  for (uint32_t py = 0; py < LitBox::H; ++py)
    for (uint32_t px = 0; px < LitBox::W; ++px)
    {
      const double x = LitBox::PixelCentre(px), y = LitBox::PixelCentre(py);
      if (x < 0.5 || x > Edge - 0.5 || y < 0.5 || y > Edge - 0.5)
        continue;
      ++rays;
      const float* got = &rgba[4 * (size_t(py) * LitBox::W + px)];
      EXPECT_NEAR(got[3], expectedAlpha, 1e-4) << px << "," << py;
      // (a) the discrete sum, and the largest relative error of the interpolated I along the ray.
      const double step = box.Params.step;
      const double j = vs::shared::vs_interleaved_gradient_noise(glm::uvec2(px, py));
      double sumA[3] = { 0, 0, 0 }, T = 1.0, interpolationError = 0.0, bending = 0.0;
      for (double a = 0.0; a < Edge; a += step)
      {
        const double b = std::min(a + step, Edge);
        const glm::dvec3 p(x, y, a + j * (b - a));
        const double A = 1.0 - std::exp(-Sigma * (b - a));
        const double exact = AnalyticLight(p, D);
        for (int k = 0; k < 3; ++k)
        {
          const double I = InterpolatedLight(light, box.Grid, p, k);
          sumA[k] += T * A * I / (4.0 * Pi);
          interpolationError = std::max(interpolationError, std::abs(I - L[k] * exact) / (L[k] * exact));
          const glm::dvec3 h(0.0, 0.0, 0.01);
          const double slope =
            (InterpolatedLight(light, box.Grid, p + h, k) - InterpolatedLight(light, box.Grid, p - h, k)) / 0.02;
          bending = std::max(bending, std::abs(slope) / I);
        }
        T *= 1.0 - A;
      }
      // (b) the 1D quadrature of the single scattering with the analytic light volume.
      double J = 0.0;
      const int n = 3200;
      for (int i = 0; i < n; ++i)
      {
        const double s = (i + 0.5) * Edge / n;
        J += std::exp(-Sigma * s) * Sigma / (4.0 * Pi) * AnalyticLight(glm::dvec3(x, y, s), D) * Edge / n;
      }
      const double bound = interpolationError + 1e-4 + std::abs(j - 0.5) * step * bending + 1e-4;
      worstBound = std::max(worstBound, bound);
      for (int k = 0; k < 3; ++k)
      {
        const double ea = std::abs(got[k] - sumA[k]) / sumA[k];
        const double eb = std::abs(got[k] - L[k] * J) / (L[k] * J);
        worstA = std::max(worstA, ea);
        worstB = std::max(worstB, eb);
        EXPECT_LT(ea, 1e-3) << "pixel " << px << "," << py << " channel " << k << ": " << got[k] << " vs " << sumA[k];
        EXPECT_LT(eb, bound) << "pixel " << px << "," << py << " channel " << k << ": " << got[k] << " vs "
                             << L[k] * J;
      }
      if (px == LitBox::W / 2 && py == LitBox::H / 2)
      {
        // Through the centre: the interpolation bends least across the box's middle.
        EXPECT_LT(std::abs(got[1] - L[1] * J) / (L[1] * J), 0.01);
        std::printf("centre ray: preview %.6f, quadrature %.6f (relative %.2e; interpolation bound %.2e)\n", got[1],
          L[1] * J, std::abs(got[1] - L[1] * J) / (L[1] * J), bound);
      }
    }
  EXPECT_GT(rays, 100);
  std::printf("%d rays: worst relative error vs the discrete sum %.2e, vs the quadrature %.2e (worst bound %.2e)\n",
    rays, worstA, worstB, worstBound);
}

// The preview draws no random numbers: two renders are bit-identical, and so are renders of other
// frames and seeds (the emission-absorption mode's jitter changes with both: checked, so the test can
// tell). A medium that varies along the rays (sigma_t 0.2 sigma and sigma in alternate slices), so
// that a jitter would show.
TEST(Preview, IsDeterministicAndNoiseFree)
{
  LitBox box{ glm::vec3(1.0f), [](int, int, int z) { return float(z % 2 == 0 ? 0.2 : 1.0); } };
  const std::vector<float> first = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  const std::vector<float> again = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  ASSERT_EQ(first.size(), again.size());
  EXPECT_EQ(0, std::memcmp(first.data(), again.data(), first.size() * sizeof(float)));
  box.Params.camera.frame = 17;
  box.Params.camera.seed = 12345;
  const std::vector<float> other = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  EXPECT_EQ(0, std::memcmp(first.data(), other.data(), first.size() * sizeof(float)));
  // The emission-absorption mode of the same box does change with the frame (its jitter): the check
  // above can tell.
  box.Params.camera.frame = 0;
  const std::vector<float> ea0 = box.Render(vs::shared::VS_EA_LIGHTING_NONE);
  box.Params.camera.frame = 17;
  const std::vector<float> ea17 = box.Render(vs::shared::VS_EA_LIGHTING_NONE);
  EXPECT_NE(0, std::memcmp(ea0.data(), ea17.data(), ea0.size() * sizeof(float)));
}

// Ambient occlusion is the preview under a constant sky of radiance lightIntensity: albedo x
// lightIntensity x the mean visibility (the light volume's alpha) for albedo x I / (4 pi), and
// I = 4 pi L V under a constant sky L.
TEST(Preview, AmbientOcclusionIsThePreviewUnderAWhiteSky)
{
  LitBox box{ glm::vec3(1.0f) };
  const std::vector<float> preview = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  const std::vector<float> ao = box.Render(vs::shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION);
  ASSERT_EQ(preview.size(), ao.size());
  double worst = 0.0, brightest = 0.0;
  for (size_t i = 0; i < ao.size(); ++i)
  {
    worst = std::max(worst, double(std::abs(ao[i] - preview[i])));
    brightest = std::max(brightest, double(ao[i]));
  }
  EXPECT_GT(brightest, 0.1);
  EXPECT_LT(worst, 1e-5);
  // The intensity scales it.
  box.Params.lightIntensity = 2.0f;
  const std::vector<float> twice = box.Render(vs::shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION);
  for (size_t i = 0; i < ao.size(); i += 4)
  {
    EXPECT_NEAR(twice[i], 2.0f * ao[i], 1e-5);
    EXPECT_EQ(twice[i + 3], ao[i + 3]);
  }
}

// A light volume of the wrong size is an InputError, not a read out of bounds; without one (a volume
// without extinction) the lit image is transparent.
TEST(Preview, MismatchedOrMissingLightVolume)
{
  LitBox box{ glm::vec3(1.0f) };
  vs::EmissionAbsorptionPass pass(box.Scene.Context);
  vs::shared::VsEmissionAbsorptionParams p = box.Params;
  p.grid.cells += glm::uvec3(1u);
  EXPECT_THROW(pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, p, {}, false, vs::shared::VS_EA_LIGHTING_PREVIEW,
                 &box.Light.Image()),
    vs::InputError);
  EXPECT_THROW(pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, box.Params, {}, false, 7u, nullptr), vs::InputError);
  const std::vector<float> dark =
    pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, box.Params, {}, false, vs::shared::VS_EA_LIGHTING_PREVIEW, nullptr);
  for (size_t i = 0; i < dark.size(); i += 4)
  {
    EXPECT_EQ(dark[i], 0.0f);
  }
}

// The preview's window image is made on the device (ea_params.h VS_EA_DISPLAY_*): the environment seen
// through the volume and the display transform, which the host did per pixel before. Through a
// perspective camera (every pixel looks in its own direction) at a box, in front of an opaque plane
// over part of the image, under an environment that varies with direction, against the host's
// arithmetic of the same:
//  - the radiance: the plain preview's, plus T x the environment's radiance along the pixel's ray
//    (bilinear between the equal-area map's texels, times the intensity) where nothing opaque is in
//    front; elsewhere unchanged;
//  - the window pixel: vs_display_pixel (display_transform.h, which the host's Monte Carlo window
//    image takes too) of that radiance, for each of painting / compositing and filmic / clamp.
// Dropping the transmittance, the intensity, the depth test or the exposure fails it.
TEST(Preview, WindowImageIsTheHostsCompositeOfItsRadiance)
{
  LitBox box{ glm::vec3(1.0f) };
  vs::EnvironmentMap map = vs::EnvironmentMap::Constant(16, glm::vec3(1.0f));
  for (int y = 0; y < map.Size; ++y)
    for (int x = 0; x < map.Size; ++x)
    {
      const glm::vec3 d = vs::shared::vs_octa_to_dir(glm::vec2((x + 0.5f) / map.Size, (y + 0.5f) / map.Size));
      float* t = &map.Radiance[3 * (size_t(y) * map.Size + x)];
      t[0] = 1.5f + d.x;
      t[1] = 1.2f + d.y;
      t[2] = 4.0f * (1.0f + d.z);
    }
  map.Finalize();
  const vs::DeviceEnvironment env(box.Scene.Context, map, 8);
  ASSERT_EQ(env.Size(), map.Size);

  const uint32_t W = 24, H = 20;
  vs::shared::VsEmissionAbsorptionParams p = box.Params;
  const glm::mat4 proj = glm::perspective(glm::radians(70.0f), float(W) / H, 1.0f, 200.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(40.0f, 30.0f, -30.0f), glm::vec3(16.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  p.camera.invViewProj = glm::inverse(proj * view);
  p.camera.width = W;
  p.camera.height = H;
  std::vector<float> depth(size_t(W) * H, 1.0f);
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W / 3; ++x)
      depth[y * W + x] = 0.999f; // an opaque plane far behind the box, over the left third
  const float intensity = 1.3f;

  vs::EmissionAbsorptionPass pass(box.Scene.Context);
  const std::vector<float> plain =
    pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, p, depth, false, vs::shared::VS_EA_LIGHTING_PREVIEW, &box.Light.Image());
  EXPECT_TRUE(pass.LastDisplay().empty());
  int covered = 0, environmentPixels = 0;
  for (uint32_t flags : { 0u, vs::shared::VS_EA_DISPLAY_COMPOSITE, vs::shared::VS_EA_DISPLAY_TONE_MAPPING,
         vs::shared::VS_EA_DISPLAY_COMPOSITE | vs::shared::VS_EA_DISPLAY_TONE_MAPPING })
  {
    vs::shared::VsEmissionAbsorptionParams q = p;
    q.display = vs::shared::VS_EA_DISPLAY_IMAGE | vs::shared::VS_EA_DISPLAY_ENVIRONMENT | flags;
    q.exposure = 0.7f;
    q.environmentSize = uint32_t(map.Size);
    q.environmentScale = intensity;
    const std::vector<float> rgba = pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, q, depth, false,
      vs::shared::VS_EA_LIGHTING_PREVIEW, &box.Light.Image(), &env.Radiance());
    const std::vector<float>& display = pass.LastDisplay();
    ASSERT_EQ(rgba.size(), 4u * W * H);
    ASSERT_EQ(display.size(), rgba.size());
    const bool composite = (flags & vs::shared::VS_EA_DISPLAY_COMPOSITE) != 0u;
    const bool toneMapping = (flags & vs::shared::VS_EA_DISPLAY_TONE_MAPPING) != 0u;
    covered = environmentPixels = 0;
    for (uint32_t y = 0; y < H; ++y)
      for (uint32_t x = 0; x < W; ++x)
      {
        const size_t i = size_t(y) * W + x;
        const glm::vec4 got = glm::make_vec4(&rgba[4 * i]), base = glm::make_vec4(&plain[4 * i]);
        const bool seesEnvironment = depth[i] >= 1.0f;
        glm::vec3 e(0.0f);
        if (seesEnvironment)
        {
          // The pixel's ray direction, as the pass unprojects it; the environment along it.
          const glm::vec2 ndc((x + 0.5f) / W * 2.0f - 1.0f, (y + 0.5f) / H * 2.0f - 1.0f);
          const glm::vec4 pn = p.camera.invViewProj * glm::vec4(ndc, -1.0f, 1.0f);
          const glm::vec4 pf = p.camera.invViewProj * glm::vec4(ndc, 1.0f, 1.0f);
          const glm::vec3 d = glm::normalize(glm::vec3(pf) / pf.w - glm::vec3(pn) / pn.w);
          const glm::vec2 uv = vs::shared::vs_dir_to_octa(d);
          for (uint32_t c = 0; c < 4u; ++c)
          {
            float weight = 0.0f;
            const glm::uvec2 t = vs::shared::vs_octa_bilinear_texel(uv, uint32_t(map.Size), c, weight);
            e += weight * map.Texel(int(t.x), int(t.y));
          }
          e *= intensity;
          ++environmentPixels;
        }
        covered += base.w > 0.05f ? 1 : 0;
        const glm::vec4 expected(glm::vec3(base) + (1.0f - base.w) * e, base.w);
        for (int k = 0; k < 4; ++k)
        {
          EXPECT_NEAR(got[k], expected[k], 1e-4f * (1.0f + std::abs(expected[k]))) << "pixel " << x << "," << y;
        }
        const glm::vec3 background = vs::shared::vs_display_rgb(q.exposure * e, toneMapping);
        const glm::vec4 window =
          vs::shared::vs_display_pixel(got, seesEnvironment, composite, background, 1.0f, q.exposure, toneMapping);
        for (int k = 0; k < 4; ++k)
        {
          EXPECT_NEAR(display[4 * i + k], window[k], 1e-4f) << "pixel " << x << "," << y << " flags " << flags;
        }
      }
  }
  // The scene has all kinds of pixels: the box over the environment and over the plane, the bare
  // environment and the bare plane.
  EXPECT_GT(covered, 20);
  EXPECT_GT(environmentPixels, 100);
  EXPECT_LT(covered, int(W * H) - 50);
  // Without its environment the flag is an error, not a read of the placeholder.
  vs::shared::VsEmissionAbsorptionParams q = p;
  q.display = vs::shared::VS_EA_DISPLAY_ENVIRONMENT;
  q.environmentSize = uint32_t(map.Size);
  EXPECT_THROW(pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, q, depth, false, vs::shared::VS_EA_LIGHTING_PREVIEW,
                 &box.Light.Image()),
    vs::InputError);
}

// ---------------------------------------------------------------------------------------------------
// The preview under full transport (issue 39): the light volume with multiple scattering
// (vsLightVolume.h, light_volume_scatter.glsl) against the two analytic answers of full transport.
namespace
{
// Replaces the scene's transfer function by one of the same extinction and a constant albedo.
void SetAlbedo(VisibilityScene& scene, double sigmaAtOne, glm::dvec3 albedo)
{
  auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 1025,
    [&](double s) { return 1.0 - std::exp(-s * sigmaAtOne); },
    [&](double, double c[3]) {
      c[0] = albedo.x;
      c[1] = albedo.y;
      c[2] = albedo.z;
    },
    1.0, 1.0);
  scene.TF = std::make_unique<vs::TransferFunctionTable>(scene.Context, samples);
}

vs::LightVolume::MultipleScattering Scattering(const VisibilityScene& scene, const vs::shared::VsEmissionAbsorptionParams& p,
  uint32_t orders, uint32_t events, uint32_t stride = vs::LightVolume::MultipleScattering().DirectionStride)
{
  vs::LightVolume::MultipleScattering m;
  m.DirectionStride = stride;
  m.Volume = scene.Volume.get();
  m.TF = scene.TF.get();
  m.Params = p.volume;
  m.Orders = orders;
  m.Events = events;
  return m;
}

}

namespace
{
// The white furnaces' density (LitBox's box): a ball falling off from its centre and a dense lobe.
float FurnaceDensity(int x, int y, int z)
{
  const glm::vec3 p(x, y, z);
  const float r = glm::length(p - glm::vec3(16.0f));
  const float lobe = glm::length(p - glm::vec3(21.0f, 12.0f, 16.0f));
  return std::min(1.0f, std::max(0.0f, 1.0f - r / 15.0f) * 2.0f + (lobe < 6.0f ? 6.0f : 0.0f));
}
}

// The white furnace: a medium of albedo 1 under a constant sky L has radiance L everywhere (full
// transport, isotropic phase): the in-scattered light is 4 pi L at every point, and a pixel shows
// L (1 - T) from the volume plus T L from the sky behind. The light volume's scattering conserves
// light exactly (light_volume_scatter.glsl: each direction's weights sum to 1 - V(c, n)), so
//   (a) with orders enough (64; no tail) and every direction every order, every cell holds 4 pi L to
//       float precision (1e-3 relative), whatever the grid's V (here a heterogeneous medium: a ball
//       with a dense lobe);
//   (b) with the defaults, 4 orders (every second direction per axis, the orders taking turns: each
//       order's quarter of the directions conserves light only approximately) and the geometric tail
//       to 1024 events, every cell within 5% (4.5% measured; 0.2% with every direction);
//   (c) the preview's pixels, L alpha, within 3% (2.2% measured; the light volume is then ~flat: its
//       interpolation adds little);
//   (d) the single-scattering preview (1 order) is darker by more than 20% on the covered pixels: the
//       test can tell.
TEST(PreviewFullTransport, WhiteFurnaceIsInvisible)
{
  const glm::dvec3 L(0.5, 1.0, 2.0);
  LitBox box{ glm::vec3(L), FurnaceDensity };
  const auto cellsOff = [&](const std::vector<float>& light) {
    double worst = 0.0;
    for (size_t i = 0; i < light.size(); i += 4)
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(light[i + k] / (4.0 * Pi * L[k]) - 1.0));
    return worst;
  };
  box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 64, 64, 1));
  const double exact = cellsOff(box.Light.Download());
  std::printf("64 orders: worst cell %.2e off 4 pi L (device %.1f ms)\n", exact, 1e3 * box.Light.LastSeconds());
  EXPECT_LT(exact, 1e-3);

  box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 4, 1024));
  const double tail = cellsOff(box.Light.Download());
  std::printf("4 orders + tail: worst cell %.2e off 4 pi L\n", tail);
  EXPECT_LT(tail, 0.05);
  const std::vector<float> full = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  double worstPixel = 0.0;
  int covered = 0;
  for (size_t i = 0; i < full.size(); i += 4)
  {
    if (full[i + 3] < 0.05f)
      continue;
    ++covered;
    for (int k = 0; k < 3; ++k)
      worstPixel = std::max(worstPixel, std::abs(full[i + k] / (L[k] * full[i + 3]) - 1.0));
  }
  std::printf("4 orders + tail: worst pixel %.2e off L alpha (%d pixels)\n", worstPixel, covered);
  EXPECT_GT(covered, 100);
  EXPECT_LT(worstPixel, 0.03);

  box.Light.Update(box.Grid, *box.Env, 1.0);
  const std::vector<float> single = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  double sumSingle = 0.0, sumFull = 0.0;
  for (size_t i = 0; i < full.size(); i += 4)
  {
    sumSingle += single[i + 1];
    sumFull += full[i + 1];
  }
  std::printf("single scattering: %.3f of full transport\n", sumSingle / sumFull);
  EXPECT_LT(sumSingle, 0.8 * sumFull);
}

// The furnace with the phase's anisotropy (the orders >= 2 in the similar medium, vsLightVolume.h): the same
// white box under the constant sky with g = 0.6 and -0.6. The exact field is uniform: I = 4 pi L and M = 0 in
// every cell. With every direction and 64 orders the light is within 2% per cell and |M| within 1% of 4 pi L
// (measured 1.2e-2 and 7.2e-3 at g 0.6), with the defaults (4 orders, the tail, stride 2) within 6% and 6%
// (5.0e-2, 4.6e-2); the first order's moment alone (what the preview's last event read before: M_1) is far
// from 0 (the test can tell).
TEST(PreviewFullTransport, WhiteFurnaceUnderAnisotropy)
{
  const glm::dvec3 L(0.5, 1.0, 2.0);
  LitBox box{ glm::vec3(L), FurnaceDensity };
  for (float g : { 0.6f, -0.6f })
    for (uint32_t orders : { 64u, 4u })
    {
      vs::LightVolume::MultipleScattering m = Scattering(box.Scene, box.Params, orders, orders == 64u ? 64u : 1024u,
        orders == 64u ? 1u : vs::LightVolume::MultipleScattering().DirectionStride);
      m.Anisotropy = g;
      box.Light.Update(box.Grid, *box.Env, 1.0, m);
      const std::vector<float> light = box.Light.Download();
      const std::vector<float> moment = box.Light.DownloadMoment();
      double worst = 0.0, worstM = 0.0, mean = 0.0;
      const size_t n = light.size() / 4;
      for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
        {
          const double r = light[4 * i + k] / (4.0 * Pi * L[k]) - 1.0;
          worst = std::max(worst, std::abs(r));
          mean += r / (3.0 * n);
          const glm::dvec3 M(moment[4 * i + k], moment[4 * (n + i) + k], moment[4 * (2 * n + i) + k]);
          worstM = std::max(worstM, glm::length(M) / (4.0 * Pi * L[k]));
        }
      std::printf("g %.1f, %u orders: worst cell %.2e off 4 pi L (mean %+.2e), worst |M| %.2e of 4 pi L\n", g, orders,
        worst, mean, worstM);
      EXPECT_LT(worst, orders == 64u ? 0.02 : 0.06) << "g " << g << ", " << orders << " orders";
      EXPECT_LT(worstM, orders == 64u ? 0.01 : 0.06) << "g " << g << ", " << orders << " orders";
    }
  vs::LightVolume::MultipleScattering first;
  first.Orders = 1;
  first.Anisotropy = 0.6f;
  box.Light.Update(box.Grid, *box.Env, 1.0, first);
  const std::vector<float> m1 = box.Light.DownloadMoment();
  const size_t n = m1.size() / 12;
  double worstM1 = 0.0;
  for (size_t i = 0; i < n; ++i)
    worstM1 = std::max(worstM1,
      glm::length(glm::dvec3(m1[4 * i + 1], m1[4 * (n + i) + 1], m1[4 * (2 * n + i) + 1])) / (4.0 * Pi * L[1]));
  std::printf("the first order's moment alone: worst |M_1| %.2e of 4 pi L\n", worstM1);
  EXPECT_GT(worstM1, 0.1);
}

// Chandrasekhar's half-space with albedo a < 1: a homogeneous slab (sigma_t 0.25 per voxel, cells of 2
// voxels: a mean free path of 2 cells) under a uniform sky of radiance 1, seen along its normal at the
// middle of its face, reflects 1 - sqrt(1 - a) H_a(1) (TestFullTransport checks the Monte Carlo kernel
// against the same). Its other faces are more than 4.6 diffusion lengths away. The single-scattering
// preview is biased by the light volume's resolution (I between cell centres, clamped at the box: the
// face's light read one voxel deep): against the first order's exact (a / 2)(1 - ln 2) its error b_1
// is some -15% here. The stated bias bound of the preview with multiple scattering: its error against
// the half-space is at most |b_1| + 3% (the transport on the cells adds at most 3% to the light
// volume's own bias), at a = 0.8, 0.9 and 0.95; and the single-scattering preview is below half of it.
TEST(PreviewFullTransport, ChandrasekharHalfSpace)
{
  const uint32_t nx = 96, nz = 48;
  const double sigma = 0.25;
  VisibilityScene scene({ { nx, nx, nz } }, [](int, int, int) { return 1.0f; }, sigma);
  const auto env = std::make_unique<vs::DeviceEnvironment>(scene.Context, vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)), 8);
  vs::VisibilityGrid grid(scene.Context);
  vs::VisibilityGridParameters g;
  g.StorageFormat = vs::VisibilityGridParameters::Format::Float32;
  g.Filtering = false;
  g.Algorithm = vs::VisibilityGridParameters::Method::BruteForce;
  g.VoxelsPerCell = 2.0;
  scene.Grid(grid, g);
  vs::shared::VsEmissionAbsorptionParams p{};
  const uint32_t W = 8, H = 8;
  // Rays along z through the face's middle (x, y in 44..52).
  p.camera = vstest::OrthoAlongZ(W, H, 44.0f, 52.0f, -10.0f, 60.0f);
  p.step = 0.25f;
  p.terminationOpacity = 0.9999f;
  const auto c = grid.Cells();
  p.grid.cells = glm::uvec3(c[0], c[1], c[2]);
  p.grid.cellSize = grid.CellSize();
  p.grid.side = grid.Side();
  vs::LightVolume light(scene.Context);
  vs::EmissionAbsorptionPass pass(scene.Context);
  for (double a : { 0.8, 0.9, 0.95 })
  {
    SetAlbedo(scene, sigma, glm::dvec3(a));
    p.volume = vs::MakeVolumeParams(scene.Geometry, *scene.TF, vs::shared::VS_INTERPOLATION_LINEAR, {});
    const double expected = vstest::ChandrasekharH(a).Reflected(1.0);
    double mean[2] = { 0.0, 0.0 };
    for (int full = 0; full < 2; ++full)
    {
      light.Update(grid, *env, 1.0, Scattering(scene, p, full ? 4 : 1, 1024));
      const std::vector<float> rgba =
        pass.Render(*scene.Volume, *scene.TF, nullptr, p, {}, false, vs::shared::VS_EA_LIGHTING_PREVIEW, &light.Image());
      for (size_t i = 0; i < rgba.size(); i += 4)
        mean[full] += rgba[i + 1] / (rgba.size() / 4);
    }
    const double expectedSingle = 0.5 * a * (1.0 - std::log(2.0));
    const double b1 = mean[0] / expectedSingle - 1.0, b = mean[1] / expected - 1.0;
    std::printf("albedo %.2f: preview %.4f, half-space %.4f: %+.1f%%; single scattering %.4f, first order %.4f: "
                "%+.1f%%\n",
      a, mean[1], expected, 100.0 * b, mean[0], expectedSingle, 100.0 * b1);
    EXPECT_LT(std::abs(b), std::abs(b1) + 0.03) << "albedo " << a;
    EXPECT_LT(std::abs(b1), 0.2) << "albedo " << a << ": the light volume's own bias";
    EXPECT_LT(mean[0], 0.5 * expected) << "albedo " << a;
  }
}

// A camera move builds nothing; what the multiple scattering reads does: the albedo, the orders, the
// events (the light volume's signature), and nothing else.
TEST(PreviewFullTransport, RebuiltOnlyWhenItsInputsChange)
{
  LitBox box{ glm::vec3(1.0f) };
  const uint64_t before = box.Light.Builds();
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 4, 1024)));
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 4, 1024)));
  vs::shared::VsEmissionAbsorptionParams moved = box.Params;
  moved.camera = vstest::OrthoAlongZ(9, 5, 3.0f, 20.0f, -5.0f, 50.0f); // the camera is no input
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, moved, 4, 1024)));
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 4, 512)));
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 3, 512)));
  SetAlbedo(box.Scene, Sigma, glm::dvec3(0.9, 0.8, 0.7));
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 3, 512)));
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, Scattering(box.Scene, box.Params, 3, 512)));
  EXPECT_EQ(box.Light.Builds(), before + 4);
  EXPECT_THROW(box.Light.Update(box.Grid, *box.Env, 1.0, vs::LightVolume::MultipleScattering()), vs::InputError);
}

// The preview's offsets per frame (issue 39, dither.h vs_dither_offset): frame 0 is the fixed pattern
// (the drag's frames, deterministic), frame k the pattern rotated by k (phi - 1); a frame is the same
// every time it is rendered. At a coarse step (3 voxels, the drag's) through shells of varying density
// (the structure a fixed pattern beats against), the mean of frames 0..7 is closer to the fine march
// (0.05 voxel) than frame 0 alone by more than 3x in RMS: the pattern's error averages out.
TEST(Preview, RotatedOffsetsAverageOutThePattern)
{
  LitBox box{ glm::vec3(1.0f), [](int x, int y, int z) {
               const float r = glm::length(glm::vec3(x, y, z) - glm::vec3(16.0f, 16.0f, -20.0f));
               return 0.5f + 0.5f * std::sin(r * 1.3f);
             } };
  box.Params.step = 3.0f;
  const std::vector<float> frame0 = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  std::vector<double> mean(frame0.size(), 0.0);
  for (uint32_t k = 0; k < 8; ++k)
  {
    box.Params.ditherFrame = k;
    const std::vector<float> f = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
    if (k == 0)
      EXPECT_EQ(0, std::memcmp(f.data(), frame0.data(), f.size() * sizeof(float))) << "frame 0 is the fixed pattern";
    if (k == 3)
    {
      const std::vector<float> again = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
      EXPECT_EQ(0, std::memcmp(f.data(), again.data(), f.size() * sizeof(float))) << "a frame is deterministic";
      EXPECT_NE(0, std::memcmp(f.data(), frame0.data(), f.size() * sizeof(float))) << "frames differ";
    }
    for (size_t i = 0; i < f.size(); ++i)
      mean[i] += f[i] / 8.0;
  }
  box.Params.ditherFrame = 0;
  box.Params.step = 0.05f;
  const std::vector<float> fine = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  double e0 = 0.0, e8 = 0.0;
  for (size_t i = 0; i < fine.size(); ++i)
  {
    if (i % 4 == 3)
      continue;
    e0 += (frame0[i] - fine[i]) * (frame0[i] - fine[i]);
    e8 += (mean[i] - fine[i]) * (mean[i] - fine[i]);
  }
  std::printf("RMS against the fine march: fixed pattern %.3e, mean of 8 rotated frames %.3e\n", std::sqrt(e0),
    std::sqrt(e8));
  EXPECT_GT(e0, 0.0);
  EXPECT_LT(std::sqrt(e8), std::sqrt(e0) / 3.0);
}

// ---------------------------------------------------------------------------------------------------
// VTK's lights in the preview (issue 38, item 4): the light volume's transmittance towards each light
// (light_volume_lights.comp) and the preview's direct lighting of each sample with it (ea_render.comp).
namespace
{
vs::shared::VsSceneLight DirectionalLight(glm::dvec3 travel, double intensity)
{
  vs::shared::VsSceneLight l{};
  const glm::dvec3 d = glm::normalize(travel);
  l.kind = vs::shared::VS_LIGHT_DIRECTIONAL;
  l.direction = glm::vec3(d);
  l.position = glm::vec3(-d);
  l.cosCone = -2.0f;
  l.irradiance = glm::vec3(float(Pi * intensity));
  l.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
  return l;
}

// A homogeneous slab of nx x nx x nz voxels (sigma per voxel, albedo a), cells of 2 voxels, under a black
// sky, seen along +z through the middle of its z = 0 face.
struct LitSlab
{
  static constexpr uint32_t nx = 48, nz = 17, W = 8, H = 8;
  VisibilityScene Scene;
  vs::VisibilityGrid Grid{ Scene.Context };
  vs::LightVolume Light{ Scene.Context };
  std::unique_ptr<vs::DeviceEnvironment> Env;
  vs::shared::VsEmissionAbsorptionParams Params{};

  LitSlab(double sigma, double a)
    : Scene({ { nx, nx, nz } }, [](int, int, int) { return 1.0f; }, sigma)
  {
    SetAlbedo(Scene, sigma, glm::dvec3(a));
    this->Env = std::make_unique<vs::DeviceEnvironment>(Scene.Context, vs::EnvironmentMap::Constant(16, glm::vec3(0.0f)), 8);
    vs::VisibilityGridParameters g;
    g.StorageFormat = vs::VisibilityGridParameters::Format::Float32;
    g.Filtering = false;
    g.Algorithm = vs::VisibilityGridParameters::Method::BruteForce;
    g.VoxelsPerCell = 2.0;
    Scene.Grid(this->Grid, g);
    this->Params.camera = vstest::OrthoAlongZ(W, H, 20.0f, 28.0f, -10.0f, 40.0f);
    this->Params.volume = vs::MakeVolumeParams(Scene.Geometry, *Scene.TF, vs::shared::VS_INTERPOLATION_LINEAR, {});
    this->Params.step = 0.25f;
    this->Params.terminationOpacity = 0.9999f;
    const auto c = this->Grid.Cells();
    this->Params.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    this->Params.grid.cellSize = this->Grid.CellSize();
    this->Params.grid.side = this->Grid.Side();
  }

  bool Update(const std::vector<vs::shared::VsSceneLight>& lights, uint32_t orders)
  {
    vs::LightVolume::MultipleScattering m = Scattering(Scene, Params, orders, 1024);
    m.Lights = lights;
    return this->Light.Update(this->Grid, *this->Env, 1.0, m);
  }

  std::vector<float> Render(bool shade = false)
  {
    vs::EmissionAbsorptionPass pass(Scene.Context);
    vs::shared::VsEmissionAbsorptionParams p = this->Params;
    p.lightCount = uint32_t(this->Light.Lights().size());
    std::copy(this->Light.Lights().begin(), this->Light.Lights().end(), p.lights);
    return pass.Render(*Scene.Volume, *Scene.TF, nullptr, p, {}, shade, vs::shared::VS_EA_LIGHTING_PREVIEW,
      &this->Light.Image(), nullptr, this->Light.Transmittance());
  }

  static double Mean(const std::vector<float>& rgba, int k)
  {
    double m = 0.0;
    for (size_t i = 0; i < rgba.size(); i += 4)
      m += rgba[i + k] / double(rgba.size() / 4);
    return m;
  }
};
}

// A directional light of intensity I through the slab's camera-facing face at cos(theta) = mu, single
// scattering (isotropic), no sky: L = a (pi I) / (4 pi) sigma (1 - exp(-k Z)) / k, k = sigma (1 + 1 / mu), the
// same integral TestSceneLights checks the Monte Carlo kernel against.
//   (a) the light volume's transmittance towards the light at the cells' centres (x, y in the slab's middle)
//       is exp(-sigma z / mu) to 1e-4 (the march at its steps' midpoints is exact in a homogeneous medium);
//   (b) the preview within 0.5% of L (-0.16% and -0.20% measured): its bias is the transmittance's interpolation between the cells'
//       centres (convex: linear interpolation of an exponential over 2 voxels errs by (sigma h / mu)^2 / 8,
//       here < 0.2%) and its clamp in the half cell at the face (there T reads the first centre's, up to
//       sigma / mu lower: ~1% of a layer that holds ~1/8 of the light), and the step's (0.25 voxel,
//       offsets of the fixed pattern);
//   (c) without the light the image is black, with 4 orders of multiple scattering it is brighter than single
//       scattering (the lights' light scatters on in the light volume), and by less than the series
//       a / (1 - a) allows.
TEST(PreviewLights, DirectionalLightOnASlabMatchesSingleScattering)
{
  const double sigma = 0.05, a = 0.8, I = 1.5;
  LitSlab slab(sigma, a);
  for (double theta : { 0.0, 0.6 })
  {
    const double mu = std::cos(theta);
    ASSERT_TRUE(slab.Update({ DirectionalLight(glm::dvec3(std::sin(theta), 0.0, mu), I) }, 1));
    ASSERT_NE(slab.Light.Transmittance(), nullptr);
    // (a)
    const std::vector<float> T = slab.Light.DownloadTransmittance();
    const auto c = slab.Grid.Cells();
    const glm::dvec3 cs(slab.Grid.CellSize());
    double worstT = 0.0;
    for (uint32_t z = 0; z < c[2]; ++z)
    {
      const uint32_t x = c[0] / 2, y = c[1] / 2;
      const double depth = (z + 0.5) * cs.z;
      const double expected = std::exp(-sigma * depth / mu);
      const float got = T[4 * ((size_t(z) * c[1] + y) * c[0] + x)];
      worstT = std::max(worstT, std::abs(got - expected) / expected);
      EXPECT_EQ(T[4 * ((size_t(z + c[2]) * c[1] + y) * c[0] + x)], 1.0f) << "lights 4-7: none";
    }
    EXPECT_LT(worstT, 1e-4) << "theta " << theta;
    // (b)
    const std::vector<float> rgba = slab.Render();
    const double Z = LitSlab::nz - 1.0, k = sigma * (1.0 + 1.0 / mu);
    const double expected = a * Pi * I / (4.0 * Pi) * sigma * (1.0 - std::exp(-k * Z)) / k;
    const double got = LitSlab::Mean(rgba, 1);
    std::printf("theta %.1f: preview %.6f, single scattering %.6f (%+.2f%%); transmittance worst %.1e\n", theta, got,
      expected, 100.0 * (got / expected - 1.0), worstT);
    EXPECT_NEAR(got, expected, 0.005 * expected) << "theta " << theta;
    if (theta == 0.0)
    {
      // (c)
      ASSERT_TRUE(slab.Update({}, 1));
      EXPECT_EQ(slab.Light.Transmittance(), nullptr);
      EXPECT_EQ(LitSlab::Mean(slab.Render(), 1), 0.0) << "no light, no sky: black";
      ASSERT_TRUE(slab.Update({ DirectionalLight(glm::dvec3(0.0, 0.0, 1.0), I) }, 4));
      const double full = LitSlab::Mean(slab.Render(), 1);
      std::printf("with 4 orders of scattering: %.6f (%.3f of single scattering)\n", full, full / got);
      EXPECT_GT(full, 1.1 * got);
      EXPECT_LT(full, got / (1.0 - a));
    }
  }
}

// The light volume is built again when a light is added, moved, recoloured or removed, and not for a
// camera move (the camera is no input of it); the same lights again build nothing.
TEST(PreviewLights, RebuiltWhenALightChangesNotForACameraMove)
{
  LitSlab slab(0.05, 0.8);
  const vs::shared::VsSceneLight key = DirectionalLight(glm::dvec3(0.3, 0.0, 1.0), 1.0);
  EXPECT_TRUE(slab.Update({ key }, 4));
  const uint64_t builds = slab.Light.Builds();
  EXPECT_FALSE(slab.Update({ key }, 4));
  slab.Params.camera = vstest::OrthoAlongZ(9, 5, 3.0f, 20.0f, -5.0f, 50.0f);
  EXPECT_FALSE(slab.Update({ key }, 4)) << "a camera move builds nothing";
  const std::vector<float> before = slab.Render();
  EXPECT_TRUE(slab.Update({ DirectionalLight(glm::dvec3(0.8, 0.0, 1.0), 1.0) }, 4)) << "moved";
  const std::vector<float> moved = slab.Render();
  EXPECT_NE(0, std::memcmp(before.data(), moved.data(), before.size() * sizeof(float)));
  vs::shared::VsSceneLight red = key;
  red.irradiance = glm::vec3(3.0f, 0.0f, 0.0f);
  EXPECT_TRUE(slab.Update({ red }, 4)) << "recoloured";
  EXPECT_TRUE(slab.Update({ red, key }, 4)) << "added";
  EXPECT_TRUE(slab.Update({ key }, 4)) << "removed";
  const std::vector<float> again = slab.Render();
  EXPECT_EQ(0, std::memcmp(before.data(), again.data(), before.size() * sizeof(float))) << "deterministic";
  EXPECT_EQ(slab.Light.Builds(), builds + 4);
  std::vector<vs::shared::VsSceneLight> nine(9, key);
  EXPECT_THROW(slab.Update(nine, 4), vs::InputError);
}

// A point light inside the volume (allowed, as in the estimate): the transmittance from each cell's centre
// runs to the light, not to the box, exp(-sigma |c - p|) to 1e-4; with the physical inverse square, the
// preview of a pixel through the light's column is brighter than that of a pixel farther from it.
TEST(PreviewLights, PointLightInsideTheVolume)
{
  const double sigma = 0.05;
  LitSlab slab(sigma, 0.8);
  vs::shared::VsSceneLight point{};
  const glm::vec3 where(24.0f, 24.0f, 8.0f);
  point.kind = vs::shared::VS_LIGHT_POSITIONAL;
  point.position = where;
  point.direction = glm::vec3(0.0f, 0.0f, 1.0f);
  point.cosCone = -2.0f;
  point.irradiance = glm::vec3(float(Pi * 50.0));
  point.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
  ASSERT_TRUE(slab.Update({ point }, 1));
  const std::vector<float> T = slab.Light.DownloadTransmittance();
  const auto c = slab.Grid.Cells();
  const glm::dvec3 cs(slab.Grid.CellSize());
  double worst = 0.0;
  for (uint32_t z = 0; z < c[2]; ++z)
    for (uint32_t y = 0; y < c[1]; ++y)
      for (uint32_t x = 0; x < c[0]; ++x)
      {
        const glm::dvec3 centre = (glm::dvec3(x, y, z) + 0.5) * cs;
        const double expected = std::exp(-sigma * glm::length(centre - glm::dvec3(where)));
        worst = std::max(worst, std::abs(T[4 * ((size_t(z) * c[1] + y) * c[0] + x)] - expected) / expected);
      }
  std::printf("point light inside: transmittance worst relative error %.1e\n", worst);
  EXPECT_LT(worst, 1e-4);
  const std::vector<float> rgba = slab.Render(); // pixels over x, y in [20, 28]: the light at their centre
  const float centre = rgba[4 * ((LitSlab::H / 2) * LitSlab::W + LitSlab::W / 2) + 1];
  const float corner = rgba[1];
  std::printf("point light inside: centre pixel %.5f, corner pixel %.5f\n", centre, corner);
  EXPECT_GT(corner, 0.0f);
  EXPECT_GT(centre, 1.5f * corner);
}

// ---------------------------------------------------------------------------------------------------
// The phase's anisotropy towards the environment (issue 39): the light volume's band-1 moment
// M = sum_n V(c, n) E_n w_n (vsLightVolume.h) and the preview's Henyey-Greenstein from I and M
// (sampling/phase_moments.h vs_hg_lobe_light, ea_render.comp).
namespace
{
// The moment's analytic value per unit sky radiance, component a: sum_n (4 pi / D^2) exp(-sigma d(x, w_n)) w_n[a].
double AnalyticMoment(glm::dvec3 x, uint32_t D, int a)
{
  double sum = 0.0;
  for (uint32_t n = 0; n < D * D; ++n)
  {
    const glm::dvec3 w(vs::SweepPlan::Direction(n, D));
    sum += 4.0 * Pi / (D * D) * std::exp(-Sigma * vstest::ExitDistance(x, w, glm::dvec3(0.0), glm::dvec3(Edge))) * w[a];
  }
  return sum;
}

// Layer `a` of the downloaded moment (cells.x x cells.y x 3 cells.z), as InterpolatedLight reads the light.
double InterpolatedMoment(const std::vector<float>& moment, const vs::VisibilityGrid& grid, glm::dvec3 x, int a, int k)
{
  const auto c = grid.Cells();
  const size_t layer = size_t(4) * c[0] * c[1] * c[2];
  const std::vector<float> slice(moment.begin() + a * layer, moment.begin() + (a + 1) * layer);
  return InterpolatedLight(slice, grid, x, k);
}

vs::LightVolume::MultipleScattering Anisotropic(float g)
{
  vs::LightVolume::MultipleScattering m;
  m.Orders = 1;
  m.Anisotropy = g;
  return m;
}

// The light volume's bands 0 and 1 at point p, trilinear as the shader reads them: I from the light (rgb), M from the
// moment's layers first .. first + 2 (rgb per channel), and with `alphaI` I from the alpha of those layers (the first
// order kept apart, layers 3 .. 5).
struct Bands
{
  glm::vec3 I, M[3];
};
Bands BandsAt(const std::vector<float>& light, const std::vector<float>& moment, const vs::VisibilityGrid& grid,
  const glm::dvec3& p, int first, bool alphaI = false)
{
  Bands b;
  for (int k = 0; k < 3; ++k)
  {
    b.I[k] = float(alphaI ? InterpolatedMoment(moment, grid, p, first + k, 3) : InterpolatedLight(light, grid, p, k));
    for (int axis = 0; axis < 3; ++axis)
      b.M[axis][k] = float(InterpolatedMoment(moment, grid, p, first + axis, k));
  }
  return b;
}

// The anisotropic preview's march on the host through pixel (px, py) of the box, as ea_render.comp marches: steps of
// Params.step, each read at the pixel's fixed offset, adding T (1 - e^{-sigma dt}) phased(p) / (4 pi). False for a
// pixel whose ray misses the box's inside (half a voxel in from its faces).
bool HostMarch(const LitBox& box, uint32_t px, uint32_t py, const std::function<glm::vec3(const glm::dvec3&)>& phased,
  glm::dvec3& sum)
{
  const double x = LitBox::PixelCentre(px), y = LitBox::PixelCentre(py);
  if (x < 0.5 || x > Edge - 0.5 || y < 0.5 || y > Edge - 0.5)
    return false;
  const double step = box.Params.step;
  const double j = vs::shared::vs_interleaved_gradient_noise(glm::uvec2(px, py));
  sum = glm::dvec3(0.0);
  double T = 1.0;
  for (double a = 0.0; a < Edge; a += step)
  {
    const double b = std::min(a + step, Edge);
    const double A = 1.0 - std::exp(-Sigma * (b - a));
    sum += T * A * glm::dvec3(phased(glm::dvec3(x, y, a + j * (b - a)))) / (4.0 * Pi);
    T *= 1.0 - A;
  }
  return true;
}
}

// The homogeneous box under a constant sky (L = 0.5, 1, 2), single scattering, seen along +z:
//  (a) the moment at every cell centre is the analytic sum to 1e-4 of 4 pi L (the grid is brute force);
//  (b) the preview with g = 0.6 and -0.6 is the discrete sum of its march on the host (the downloaded I and
//      M trilinear, vs_hg_lobe_light at d = +z, the pixel's fixed offset) to 1e-3 relative: the shader reads
//      the moment's layers and the camera's direction as the math has them. The preview with g != 0 differs
//      from the isotropic one by more than 1% at the centre (the test can tell);
//  (c) g = 0 with the moment bound, or g != 0 without it, is the isotropic preview bit for bit.
TEST(PreviewAnisotropy, MomentIsAnalyticAndThePreviewIsItsMarch)
{
  const glm::dvec3 L(0.5, 1.0, 2.0);
  LitBox box{ glm::vec3(L) };
  const std::vector<float> isotropic = box.Render(vs::shared::VS_EA_LIGHTING_PREVIEW);
  EXPECT_EQ(box.Light.Moment(), nullptr) << "no moment at g = 0";
  ASSERT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(0.6f)));
  ASSERT_NE(box.Light.Moment(), nullptr);
  const std::vector<float> light = box.Light.Download();
  const std::vector<float> moment = box.Light.DownloadMoment();
  const uint32_t D = box.Grid.Side();
  const auto c = box.Grid.Cells();
  ASSERT_EQ(moment.size(), size_t(12) * c[0] * c[1] * c[2]);
  // (a)
  const glm::dvec3 cs(box.Grid.CellSize());
  double worst = 0.0;
  for (uint32_t z = 0; z < c[2]; ++z)
    for (uint32_t y = 0; y < c[1]; ++y)
      for (uint32_t x = 0; x < c[0]; ++x)
      {
        const glm::dvec3 centre = (glm::dvec3(x, y, z) + 0.5) * cs;
        for (int a = 0; a < 3; ++a)
          for (int k = 0; k < 3; ++k)
          {
            const double expected = L[k] * AnalyticMoment(centre, D, a);
            const float got = moment[4 * (((size_t(z) + a * c[2]) * c[1] + y) * c[0] + x) + k];
            worst = std::max(worst, std::abs(got - expected) / (4.0 * Pi * L[k]));
          }
      }
  std::printf("moment: worst error %.1e of 4 pi L\n", worst);
  EXPECT_LT(worst, 1e-4);
  // (b)
  for (float g : { 0.6f, -0.6f })
  {
    box.Params.anisotropy = g;
    vs::EmissionAbsorptionPass pass(box.Scene.Context);
    const std::vector<float> rgba = pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, box.Params, {}, false,
      vs::shared::VS_EA_LIGHTING_PREVIEW, &box.Light.Image(), nullptr, nullptr, box.Light.Moment());
    double worstA = 0.0;
    for (uint32_t py = 0; py < LitBox::H; ++py)
      for (uint32_t px = 0; px < LitBox::W; ++px)
      {
        glm::dvec3 sum;
        const auto lobe = [&](const glm::dvec3& p) {
          const Bands b = BandsAt(light, moment, box.Grid, p, 0);
          return vs::shared::vs_hg_lobe_light(b.I, b.M[0], b.M[1], b.M[2], glm::vec3(0, 0, 1), g);
        };
        if (!HostMarch(box, px, py, lobe, sum))
          continue;
        const float* got = &rgba[4 * (size_t(py) * LitBox::W + px)];
        for (int k = 0; k < 3; ++k)
        {
          worstA = std::max(worstA, std::abs(got[k] - sum[k]) / sum[k]);
          EXPECT_LT(std::abs(got[k] - sum[k]) / sum[k], 1e-3) << "g " << g << " pixel " << px << "," << py;
        }
      }
    const size_t centre = 4 * (size_t(LitBox::H / 2) * LitBox::W + LitBox::W / 2) + 1;
    std::printf("g %.1f: worst relative error against the host's march %.1e; centre pixel %.5f, isotropic %.5f\n", g,
      worstA, rgba[centre], isotropic[centre]);
    EXPECT_GT(std::abs(rgba[centre] / isotropic[centre] - 1.0f), 0.01f);
    // (c) g != 0 without the moment: isotropic.
    const std::vector<float> without = pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, box.Params, {}, false,
      vs::shared::VS_EA_LIGHTING_PREVIEW, &box.Light.Image());
    EXPECT_EQ(0, std::memcmp(without.data(), isotropic.data(), without.size() * sizeof(float)));
  }
  // (c) g = 0 with the moment bound.
  box.Params.anisotropy = 0.0f;
  vs::EmissionAbsorptionPass pass(box.Scene.Context);
  const std::vector<float> zero = pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, box.Params, {}, false,
    vs::shared::VS_EA_LIGHTING_PREVIEW, &box.Light.Image(), nullptr, nullptr, box.Light.Moment());
  EXPECT_EQ(0, std::memcmp(zero.data(), isotropic.data(), zero.size() * sizeof(float))) << "g = 0: today's preview";
}

// Two lobes at the preview's last event (the orders >= 2 under g < 0, vsLightVolume.h): the light volume keeps
// the first order apart in layers 3 .. 5 of its moment, M_1 and I_1 as a single-scattering build makes them (to
// 1e-6 of 4 pi L), and the preview is the host's march of I_1 f_HG(m_1.d; g rho_1) + (I - I_1) f_HG(m_r.d; g rho_r)
// with M_r = M - M_1, to 1e-3 relative; one lobe of the whole light differs from it by more than 1e-3 (the test
// can tell). The box of the test above, 4 orders and the tail, g = -0.6 and -0.3; at g = 0.6 the moment has its 3
// layers (one lobe of the whole light, as before).
TEST(PreviewFullTransport, TwoLobesTheFirstOrderApart)
{
  const glm::dvec3 L(0.5, 1.0, 2.0);
  LitBox box{ glm::vec3(L) };
  const auto c = box.Grid.Cells();
  const size_t n = size_t(c[0]) * c[1] * c[2];
  {
    vs::LightVolume::MultipleScattering m = Scattering(box.Scene, box.Params, 4, 1024);
    m.Anisotropy = 0.6f;
    ASSERT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, m));
    EXPECT_EQ(box.Light.DownloadMoment().size(), 12 * n) << "g 0.6: one lobe, 3 layers";
  }
  for (float g : { -0.6f, -0.3f })
  {
    ASSERT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(g)));
    const std::vector<float> light1 = box.Light.Download();
    const std::vector<float> moment1 = box.Light.DownloadMoment();
    ASSERT_EQ(moment1.size(), 12 * n);
    vs::LightVolume::MultipleScattering m = Scattering(box.Scene, box.Params, 4, 1024);
    m.Anisotropy = g;
    ASSERT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, m));
    const std::vector<float> light = box.Light.Download();
    const std::vector<float> moment = box.Light.DownloadMoment();
    ASSERT_EQ(moment.size(), 24 * n) << "6 layers: the first order apart";
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k)
        {
          worst = std::max(worst, std::abs(moment[4 * ((3 + a) * n + i) + k] - moment1[4 * (a * n + i) + k]) / (4.0 * Pi * L[k]));
          worst = std::max(worst, std::abs(moment[4 * ((3 + a) * n + i) + 3] - light1[4 * i + a]) / (4.0 * Pi * L[a]));
        }
    std::printf("g %.1f: the first order apart, worst %.1e of 4 pi L\n", g, worst);
    EXPECT_LT(worst, 1e-6);

    box.Params.anisotropy = g;
    vs::EmissionAbsorptionPass pass(box.Scene.Context);
    const std::vector<float> rgba = pass.Render(*box.Scene.Volume, *box.Scene.TF, nullptr, box.Params, {}, false,
      vs::shared::VS_EA_LIGHTING_PREVIEW, &box.Light.Image(), nullptr, nullptr, box.Light.Moment());
    double worstA = 0.0, oneLobe = 0.0;
    const glm::vec3 d(0, 0, 1);
    const auto two = [&](const glm::dvec3& p) {
      const Bands all = BandsAt(light, moment, box.Grid, p, 0), first = BandsAt(light, moment, box.Grid, p, 3, true);
      return vs::shared::vs_hg_lobe_light(first.I, first.M[0], first.M[1], first.M[2], d, g) +
        vs::shared::vs_hg_lobe_light(glm::max(all.I - first.I, glm::vec3(0.0f)), all.M[0] - first.M[0],
          all.M[1] - first.M[1], all.M[2] - first.M[2], d, g);
    };
    const auto one = [&](const glm::dvec3& p) {
      const Bands all = BandsAt(light, moment, box.Grid, p, 0);
      return vs::shared::vs_hg_lobe_light(all.I, all.M[0], all.M[1], all.M[2], d, g);
    };
    for (uint32_t py = 0; py < LitBox::H; ++py)
      for (uint32_t px = 0; px < LitBox::W; ++px)
      {
        glm::dvec3 sum, sumOne;
        if (!HostMarch(box, px, py, two, sum) || !HostMarch(box, px, py, one, sumOne))
          continue;
        const float* got = &rgba[4 * (size_t(py) * LitBox::W + px)];
        for (int k = 0; k < 3; ++k)
        {
          worstA = std::max(worstA, std::abs(got[k] - sum[k]) / sum[k]);
          oneLobe = std::max(oneLobe, std::abs(sumOne[k] - sum[k]) / sum[k]);
          EXPECT_LT(std::abs(got[k] - sum[k]) / sum[k], 1e-3) << "g " << g << " pixel " << px << "," << py;
        }
      }
    std::printf("g %.1f: two lobes, worst relative error against the host's march %.1e; one lobe differs by up to "
                "%.1e\n", g, worstA, oneLobe);
    EXPECT_GT(oneLobe, 1e-3);
  }
}

// The light volume is built again when g becomes non-zero (the moment), not for another g, not for g back to
// 0 (the moment is kept) and not for a camera move; a build for another reason at g = 0 drops the moment; a
// g outside (-1, 1) is an error.
TEST(PreviewAnisotropy, RebuiltWhenGBecomesNonZeroNotForACameraMove)
{
  LitBox box{ glm::vec3(1.0f) }; // built at g = 0
  const uint64_t before = box.Light.Builds();
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(0.0f)));
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(0.6f))) << "g becomes non-zero";
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(-0.3f))) << "another g";
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(0.0f))) << "back to 0: the moment is kept";
  EXPECT_NE(box.Light.Moment(), nullptr);
  // The camera is no input (the multiple scattering's Params carry the volume, not the view).
  vs::LightVolume::MultipleScattering m = Scattering(box.Scene, box.Params, 4, 1024);
  m.Anisotropy = 0.9f;
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 1.0, m));
  vs::shared::VsEmissionAbsorptionParams moved = box.Params;
  moved.camera = vstest::OrthoAlongZ(9, 5, 3.0f, 20.0f, -5.0f, 50.0f);
  vs::LightVolume::MultipleScattering m2 = Scattering(box.Scene, moved, 4, 1024);
  m2.Anisotropy = 0.9f;
  EXPECT_FALSE(box.Light.Update(box.Grid, *box.Env, 1.0, m2)) << "a camera move";
  EXPECT_TRUE(box.Light.Update(box.Grid, *box.Env, 2.0, Anisotropic(0.0f))) << "the intensity changed";
  EXPECT_EQ(box.Light.Moment(), nullptr) << "built at g = 0: no moment";
  EXPECT_EQ(box.Light.Builds(), before + 3);
  EXPECT_THROW(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(1.0f)), vs::InputError);
  EXPECT_THROW(box.Light.Update(box.Grid, *box.Env, 1.0, Anisotropic(std::nanf(""))), vs::InputError);
}
