// The vtkVolumeProperty's gradient opacity (issue 14): the factor per voxel g = GO(|grad s|)
// (vsGradientOpacity.h) against analytic gradients; the majorants (brick max sigma_t x brick max g) against
// the extinction sampled along rays; the Monte Carlo kernel with a factor volume against the same extinction
// baked into the scalars (per-pixel z-scores: unbiased), through the brick walk, the cell walk, the reservoir
// camera and the control extinctions, under trilinear and nearest interpolation; and the sweeps against the
// baked volume.
#include "vsGradientOpacity.h"
#include "vsRenderTestScene.h"
#include "vsVolumeScene.h"

#include "sampling/interpolation.h"
#include "sampling/strategies.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace vs::shared;
using vstest::Agreement;
using vstest::Compare;
using vstest::RenderScene;

namespace
{
const char* kNames[] = { "Uniform", "Environment", "Visibility", "Combined", "TwoStep" };

vtkSmartPointer<vtkImageData> Image(
  std::array<int, 3> dims, std::array<double, 3> spacing, const std::function<float(int, int, int)>& value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(vtkIdType(dims[0]) * dims[1] * dims[2]);
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x)
        a->SetValue((vtkIdType(z) * dims[1] + y) * dims[0] + x, value(x, y, z));
  image->GetPointData()->SetScalars(a);
  return image;
}

std::vector<float> Values(vtkImageData* image)
{
  auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  return std::vector<float>(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfTuples());
}

// Trilinear interpolation of v (dims) at index point p, clamped as the device does.
double Trilinear(const std::vector<float>& v, std::array<uint32_t, 3> d, glm::dvec3 p)
{
  glm::dvec3 q = glm::clamp(p, glm::dvec3(0.0), glm::dvec3(d[0] - 1, d[1] - 1, d[2] - 1));
  glm::ivec3 i0 = glm::ivec3(glm::floor(q));
  glm::ivec3 i1 = glm::min(i0 + 1, glm::ivec3(d[0] - 1, d[1] - 1, d[2] - 1));
  glm::dvec3 f = q - glm::dvec3(i0);
  auto at = [&](int x, int y, int z) { return double(v[(size_t(z) * d[1] + y) * d[0] + x]); };
  double c00 = at(i0.x, i0.y, i0.z) * (1 - f.x) + at(i1.x, i0.y, i0.z) * f.x;
  double c10 = at(i0.x, i1.y, i0.z) * (1 - f.x) + at(i1.x, i1.y, i0.z) * f.x;
  double c01 = at(i0.x, i0.y, i1.z) * (1 - f.x) + at(i1.x, i0.y, i1.z) * f.x;
  double c11 = at(i0.x, i1.y, i1.z) * (1 - f.x) + at(i1.x, i1.y, i1.z) * f.x;
  return (c00 * (1 - f.y) + c10 * f.y) * (1 - f.z) + (c01 * (1 - f.y) + c11 * f.y) * f.z;
}

// The table's extinction at scalar s (linear between entries, clamped), as vs_classify.
double TableExtinction(const vs::TransferFunctionSamples& t, double s)
{
  const size_t n = t.Size();
  double x = std::clamp((s - t.ScalarMin) / (double(t.ScalarMax) - t.ScalarMin) * double(n - 1), 0.0, double(n - 1));
  size_t i0 = std::min(size_t(x), n - 1), i1 = std::min(i0 + 1, n - 1);
  double f = x - double(i0);
  return t.Entries[4 * i0 + 3] * (1 - f) + t.Entries[4 * i1 + 3] * f;
}

// A heterogeneous pattern in [0.3, 1], 0 for x <= 8: in a volume 25 voxels wide, the first brick along x
// (voxels 0-8) is empty (skipped), the second holds zeros (no control), the third none (a control extinction
// above 0: residual and decomposition tracking have work to do).
float Pattern(int x, int y, int z)
{
  return x > 8 ? 0.3f + 0.7f * float((x * 7 + y * 3 + z * 5) % 11) / 10.0f : 0.0f;
}
} // namespace

// Central differences in world units: on s = 3 x (spacing 2 along x, so 1.5 per world unit) and s = 2 y
// (spacing 0.5: 4 per world unit) the magnitude is exact at every voxel (one-sided at the faces), and g is
// the gradient-opacity function there; a non-finite voxel gets 0 and its neighbours take the one-sided
// difference away from it.
TEST(GradientOpacity, FactorOfAnalyticGradients)
{
  vtkNew<vtkPiecewiseFunction> go;
  go->AddPoint(0.0, 0.0);
  go->AddPoint(10.0, 1.0); // g = |grad s| / 10
  const double spacing[3] = { 2.0, 0.5, 1.0 };
  const std::array<uint32_t, 3> dims{ { 6, 5, 4 } };
  std::vector<float> s(6 * 5 * 4);
  for (uint32_t z = 0; z < 4; ++z)
    for (uint32_t y = 0; y < 5; ++y)
      for (uint32_t x = 0; x < 6; ++x)
        s[(z * 5 + y) * 6 + x] = 3.0f * float(x) + 2.0f * float(y);
  // |grad s| = sqrt((3 / 2)^2 + (2 / 0.5)^2) = sqrt(2.25 + 16).
  const double expected = std::sqrt(2.25 + 16.0) / 10.0;
  std::vector<float> g = vs::GradientOpacityFactor(s.data(), dims, spacing, go);
  for (float v : g)
    EXPECT_NEAR(v, expected, 1e-5);
  s[(1 * 5 + 2) * 6 + 3] = std::numeric_limits<float>::quiet_NaN();
  g = vs::GradientOpacityFactor(s.data(), dims, spacing, go);
  EXPECT_EQ(g[(1 * 5 + 2) * 6 + 3], 0.0f) << "a non-finite voxel";
  EXPECT_NEAR(g[(1 * 5 + 2) * 6 + 2], expected, 1e-5) << "its neighbour, one-sided";
  EXPECT_NEAR(g[(1 * 5 + 2) * 6 + 4], expected, 1e-5) << "its neighbour, one-sided";
  // Values above 1 are clamped (sigma_t x g never exceeds the table's cap).
  vtkNew<vtkPiecewiseFunction> big;
  big->AddPoint(0.0, 5.0);
  big->AddPoint(1.0, 5.0);
  for (float v : vs::GradientOpacityFactor(s.data(), dims, spacing, big))
    EXPECT_LE(v, 1.0f);

  vtkNew<vtkVolumeProperty> property;
  EXPECT_FALSE(vs::HasEffectiveGradientOpacity(property)) << "no gradient opacity set";
  vtkNew<vtkPiecewiseFunction> ones;
  ones->AddPoint(0.0, 1.0);
  ones->AddPoint(5.0, 1.0);
  property->SetGradientOpacity(ones);
  EXPECT_FALSE(vs::HasEffectiveGradientOpacity(property)) << "1 everywhere";
  property->SetGradientOpacity(go);
  EXPECT_TRUE(vs::HasEffectiveGradientOpacity(property));
  property->DisableGradientOpacityOn();
  EXPECT_FALSE(vs::HasEffectiveGradientOpacity(property)) << "disabled";
}

// The majorants stay an upper bound (and the controls a lower bound) of what the renderer samples,
// sigma_t(s(p)) x g(p) with s and g trilinear, at points along random rays through a noisy ball whose
// homogeneous interior the gradient opacity zeroes; the bricks of that interior become empty (skipped by
// every tracker and sweep), and a new gradient opacity is a new extinction.
TEST(GradientOpacity, MajorantBoundsTheExtinctionAlongRays)
{
  const int n = 48;
  std::mt19937 noise(7);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
  auto image = Image({ { n, n, n } }, { { 0.7, 0.7, 0.7 } },
    [&](int x, int y, int z)
    {
      const double c = 0.5 * (n - 1), r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
      return r < 22.0 ? 0.8f + (r > 19.0 ? jitter(noise) : 0.0f) : 0.0f;
    });
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.9);
  vtkNew<vtkPiecewiseFunction> go;
  go->AddPoint(0.0, 0.0);
  go->AddPoint(0.05, 0.0);
  go->AddPoint(0.5, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();

  vs::VolumeScene scene(vs::Context::Default());
  scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  const double emptyWithout = scene.Majorants().EmptyFraction();
  EXPECT_FALSE(scene.HasGradientOpacity());
  EXPECT_EQ(scene.Volume().Factor(), nullptr);
  property->SetGradientOpacity(go);
  auto changes = scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  EXPECT_TRUE(changes.Extinction) << "a gradient opacity is a new extinction";
  EXPECT_TRUE(changes.TransferFunction) << "the property's MTime covers its gradient-opacity function";
  ASSERT_TRUE(scene.HasGradientOpacity());
  ASSERT_NE(scene.Volume().Factor(), nullptr);
  const double emptyWith = scene.Majorants().EmptyFraction();
  std::printf("[ gradient opacity ] empty bricks %.3f without, %.3f with "
              "(factor in %.3f s)\n",
    emptyWithout, emptyWith, scene.LastFactorSeconds());
  EXPECT_GT(emptyWith, emptyWithout + 0.01) << "the homogeneous interior's bricks are empty";

  const std::vector<float> s = Values(image);
  const double spacing[3] = { 0.7, 0.7, 0.7 };
  const auto dims = scene.Volume().Dims();
  const std::vector<float> g = vs::GradientOpacityFactor(s.data(), dims, spacing, go);
  const auto& tf = scene.TF().Samples();
  const auto& majorants = scene.Majorants().Majorants();
  const auto& controls = scene.Majorants().Controls();
  const auto bricks = scene.Majorants().Bricks();
  const double B = scene.Majorants().BrickSize();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  uint64_t samples = 0, positive = 0, violations = 0, controlViolations = 0;
  double tightest = 0.0;
  for (int ray = 0; ray < 2000; ++ray)
  {
    glm::dvec3 o(u(rng) * (n - 1), u(rng) * (n - 1), u(rng) * (n - 1));
    double ct = 2.0 * u(rng) - 1.0, ph = 2.0 * M_PI * u(rng);
    glm::dvec3 d(std::sqrt(1 - ct * ct) * std::cos(ph), std::sqrt(1 - ct * ct) * std::sin(ph), ct);
    for (double t = 0.0; t < 2.0 * n; t += 0.173)
    {
      glm::dvec3 p = o + t * d;
      if (glm::any(glm::lessThan(p, glm::dvec3(0.0))) || glm::any(glm::greaterThan(p, glm::dvec3(n - 1))))
        break;
      const double sigma = TableExtinction(tf, Trilinear(s, dims, p)) * Trilinear(g, dims, p);
      glm::ivec3 b = glm::min(glm::ivec3(glm::floor(p / B)), glm::ivec3(bricks[0] - 1, bricks[1] - 1, bricks[2] - 1));
      const size_t bi = (size_t(b.z) * bricks[1] + b.y) * bricks[0] + b.x;
      ++samples;
      positive += sigma > 0.0;
      violations += sigma > double(majorants[bi]) * (1.0 + 1e-6) + 1e-12;
      controlViolations += sigma < double(controls[bi]) * (1.0 - 1e-6) - 1e-12;
      if (majorants[bi] > 0.0f)
        tightest = std::max(tightest, sigma / majorants[bi]);
    }
  }
  std::printf("[ gradient opacity ] %llu samples (%llu with extinction): %llu "
              "above the majorant, %llu below the "
              "control; largest sigma / majorant %.3f\n",
    (unsigned long long)samples, (unsigned long long)positive, (unsigned long long)violations,
    (unsigned long long)controlViolations, tightest);
  EXPECT_GT(samples, 20000u);
  EXPECT_GT(positive, 2000u);
  EXPECT_EQ(violations, 0u);
  EXPECT_EQ(controlViolations, 0u);
  EXPECT_GT(tightest, 0.5) << "a bound, but not a loose one";

  // A new function (same property) recomputes the factor; the same function keeps it.
  const int builds = scene.FactorBuilds();
  scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  EXPECT_EQ(scene.FactorBuilds(), builds) << "nothing changed";
  go->AddPoint(0.3, 0.2);
  changes = scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  EXPECT_EQ(scene.FactorBuilds(), builds + 1);
  EXPECT_TRUE(changes.Extinction);
  property->DisableGradientOpacityOn();
  changes = scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  EXPECT_EQ(scene.FactorBuilds(), builds + 2);
  EXPECT_TRUE(changes.Extinction);
  EXPECT_EQ(scene.Volume().Factor(), nullptr);
  EXPECT_EQ(scene.Majorants().EmptyFraction(), emptyWithout) << "the majorants of the scalars alone again";
}

// The kernel with a factor volume is unbiased: a constant scalar (sigma_t = 0.3 everywhere) scaled by the
// factor g = Pattern renders what the scalars s = Pattern under the same linear transfer function render (the
// same extinction field, sigma_t = 0.3 trilinear(g)), pixel by pixel within the standard errors (the z^2 sum
// of TestMonteCarlo.cxx), with the brick walk, the cell walk forced everywhere, the reservoir camera and the
// control extinctions. Under nearest interpolation, scalars Pattern' scaled by Pattern render what Pattern' x
// Pattern renders.
TEST(MonteCarlo, GradientOpacityFactorIsUnbiased)
{
  const auto env =
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f));
  const std::array<uint32_t, 3> dims{ { 25, 15, 13 } };
  for (uint32_t interpolation : { VS_INTERPOLATION_LINEAR, VS_INTERPOLATION_NEAREST })
  {
    const bool nearest = interpolation == VS_INTERPOLATION_NEAREST;
    auto other = [](int x, int y, int z) { return 0.3f + 0.7f * float((x * 5 + y * 11 + z * 3) % 7) / 6.0f; };
    std::function<float(int, int, int)> scalar = [&](int x, int y, int z) { return nearest ? other(x, y, z) : 1.0f; };
    // sigma_t up to 0.3 per voxel: optically thin to thick across the image, so the extinction's scale shows
    // (a thick medium's single scattering hardly depends on it).
    RenderScene scaled(dims, scalar, 0.3, glm::vec3(0.8f, 0.7f, 0.6f), env);
    scaled.ScaleExtinction(Pattern);
    scaled.Grid->Compute(*scaled.Volume, *scaled.TF, *scaled.Majorants, scaled.Geometry, {}, {});
    RenderScene baked(
      dims, [&](int x, int y, int z) { return scalar(x, y, z) * Pattern(x, y, z); }, 0.3, glm::vec3(0.8f, 0.7f, 0.6f),
      env);
    EXPECT_GT(scaled.Majorants->EmptyFraction(), 0.2) << "the factor's empty bricks are empty";
    EXPECT_EQ(scaled.Majorants->EmptyFraction(), baked.Majorants->EmptyFraction());
    EXPECT_GT(*std::max_element(scaled.Majorants->Controls().begin(), scaled.Majorants->Controls().end()), 0.02f)
      << "a brick with a control extinction";
    struct Variant
    {
      const char* name;
      float refine;
      uint32_t camera, control;
    };
    for (const Variant& v :
      { Variant{ "brick walk", 0.0f, VS_CAMERA_COLLISION, 0u }, Variant{ "cell walk", 0.05f, VS_CAMERA_COLLISION, 0u },
        Variant{ "reservoir camera", 0.0f, VS_CAMERA_RESERVOIR, 0u },
        Variant{ "controls", 0.0f, VS_CAMERA_COLLISION, VS_CONTROL_SHADOW | VS_CONTROL_CAMERA } })
    {
      for (uint32_t strategy : { VS_STRATEGY_UNIFORM, VS_STRATEGY_TWO_STEP })
      {
        if (strategy == VS_STRATEGY_UNIFORM && v.refine == 0.0f && v.camera == VS_CAMERA_COLLISION && v.control != 0u)
          continue; // the controls with TwoStep only (the test's time)
        if (strategy == VS_STRATEGY_UNIFORM && v.camera == VS_CAMERA_RESERVOIR)
          continue;
        auto p = baked.Params(8, 8, -2.0f, 26.0f, strategy, 512, 3u, true);
        p.cellWalkDepth = v.refine;
        p.cameraEstimator = v.camera;
        p.volume.interpolation = interpolation;
        p.controlExtinction = v.control;
        auto [a, va] = baked.Render(p, 2);
        const double n = baked.LastSamples;
        auto q = scaled.Params(8, 8, -2.0f, 26.0f, strategy, 512, 0x9e3779b9u,
          true); // independent samples
        q.cellWalkDepth = p.cellWalkDepth;
        q.cameraEstimator = p.cameraEstimator;
        q.volume.interpolation = p.volume.interpolation;
        q.shadowRays = p.shadowRays;
        q.controlExtinction = v.control;
        auto [b, vb] = scaled.Render(q, 2);
        const Agreement agreement = Compare(a, va, b, vb, n);
        const std::string what = std::string(kNames[strategy]) + ", " + v.name + (nearest ? ", nearest" : ", linear");
        std::printf("[ gradient opacity ] %s: chi2 %.1f dof %d (bound %.1f)\n", what.c_str(), agreement.chi2,
          agreement.dof, agreement.Bound());
        EXPECT_GT(agreement.dof, 150) << what;
        EXPECT_LT(agreement.chi2, agreement.Bound()) << what;
        if (strategy == VS_STRATEGY_TWO_STEP && v.refine == 0.0f && v.camera == VS_CAMERA_COLLISION && !v.control)
        {
          // The test's power: an extinction 15% off (the factor 0.85 g baked in) is rejected.
          RenderScene wrong(
            dims, [&](int x, int y, int z) { return 0.85f * scalar(x, y, z) * Pattern(x, y, z); }, 0.3,
            glm::vec3(0.8f, 0.7f, 0.6f), env);
          auto [c, vc] = wrong.Render(p, 2);
          const Agreement off = Compare(c, vc, b, vb, n);
          std::printf("[ gradient opacity ] %s against 0.85 x the extinction: "
                      "chi2 %.1f dof %d (bound %.1f)\n",
            what.c_str(), off.chi2, off.dof, off.Bound());
          EXPECT_GT(off.chi2, off.Bound()) << what << ": a 15% error must be seen";
        }
      }
    }
  }
}

// The sweeps see the factor: the full-resolution march samples sigma_t(s) x g, the pooled volume pools
// sigma_t x g at the voxels, so the grid of the scaled volume is that of the baked one (the same extinction
// field up to the rounding of the table), pooled or not; without the factor the grid differs.
TEST(VisibilityGrid, GradientOpacityFactorMatchesBakedExtinction)
{
  const std::array<uint32_t, 3> dims{ { 25, 23, 21 } };
  vstest::VisibilityScene scaled(
    dims, [](int, int, int) { return 1.0f; }, 0.6);
  vstest::VisibilityScene baked(dims, Pattern, 0.6);
  vs::VisibilityGridParameters p;
  p.StorageFormat = vs::VisibilityGridParameters::Format::Float32;
  for (uint32_t pooling : { 1u, 2u })
  {
    p.ExtinctionPooling = pooling;
    vs::VisibilityGrid plain(scaled.Context);
    const std::vector<float> unscaled = scaled.Grid(plain, p);
    scaled.ScaleExtinction(Pattern);
    vs::VisibilityGrid a(scaled.Context), b(baked.Context);
    const std::vector<float> ga = scaled.Grid(a, p), gb = baked.Grid(b, p);
    ASSERT_EQ(ga.size(), gb.size());
    double diff = 0.0, diffUnscaled = 0.0;
    for (size_t i = 0; i < ga.size(); ++i)
    {
      diff = std::max(diff, std::abs(double(ga[i]) - gb[i]));
      diffUnscaled = std::max(diffUnscaled, std::abs(double(unscaled[i]) - gb[i]));
    }
    std::printf("[ gradient opacity ] pooling %u: largest |V scaled - V baked| "
                "%.2e (unscaled: %.3f)\n",
      pooling, diff, diffUnscaled);
    EXPECT_LT(diff, 1e-4) << "pooling " << pooling;
    EXPECT_GT(diffUnscaled, 0.1) << "pooling " << pooling << ": the factor must matter for this test to mean anything";
    // Back to no factor for the next pooling.
    scaled.Volume->SetFactor(nullptr);
    scaled.Majorants->SetFactor(nullptr);
    scaled.Majorants->UpdateMajorants(scaled.TF->Samples());
  }
}
