// The numerical-stability stress suite (issue 5), fast part: hostile scales, lights,
// geometry and data through the mapper, each checked for errors, NaN/Inf radiance and
// physically impossible brightness (vsStressScene.h). Long variants: `vissweep bench stress`.
#include "vsStressScene.h"
#include "vsContext.h"

#include "vtkDoubleArray.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPlane.h"

#include <gtest/gtest.h>

#if VS_STRESS_ASAN
#if __has_include(<sanitizer/allocator_interface.h>)
#include <sanitizer/allocator_interface.h>
#else
// gcc 12 ships no allocator_interface.h, but its libasan exports the function (the same
// declaration as compiler-rt's header).
extern "C" size_t __sanitizer_get_current_allocated_bytes(void);
#endif
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <malloc.h>
#include <limits>
#include <random>
#include <string>

using namespace vsstress;

namespace
{
const int N = 12; // voxels per side of the default ball

vtkSmartPointer<vtkImageData> DefaultBall()
{
  return MakeVolume(N, N, N, [](int x, int y, int z) { return Ball(x, y, z, N, N, N); });
}

double MaxRadiance(vtkEnvironmentMapSource* env)
{
  env->Update();
  vtkDataArray* r = env->GetOutput()->GetPointData()->GetArray("Radiance");
  double m = 0.0;
  for (vtkIdType i = 0; i < r->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      m = std::max(m, r->GetComponent(i, c));
  return m * env->GetIntensity();
}

double MaxRadiance(vtkImageData* env)
{
  vtkDataArray* r = env->GetPointData()->GetArray("Radiance");
  double m = 0.0;
  for (vtkIdType i = 0; i < r->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      m = std::max(m, r->GetComponent(i, c));
  return m;
}

const int kStrategies[] = { vtkVisibilitySweepVolumeMapper::Uniform, vtkVisibilitySweepVolumeMapper::Environment,
  vtkVisibilitySweepVolumeMapper::TwoStep };

long ResidentKilobytes()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * 4;
}

#if !VS_STRESS_ASAN
// Bytes the program holds from malloc (every arena, plus blocks malloc serves by mmap): what a
// leak grows. The resident set also moves with one-time costs that are no leak, e.g. a new
// malloc arena or the JIT's code pages when lavapipe compiles a pipeline for the first time:
// RSS grew once by 26 MB within the 900 changes (a full-suite run; +80-140 KB in every other
// run, and the live heap stays flat), over the old 20 MB bound.
long LiveHeapKilobytes()
{
  const struct mallinfo2 m = mallinfo2();
  return long((m.uordblks + m.hblkhd) / 1024);
}
#endif

#if VS_STRESS_ASAN
// Under AddressSanitizer the resident set is no measure of leaks: freed blocks sit in ASan's
// quarantine (up to 256 MB) and its allocator keeps its own caches, so RSS grew by ~600 MB
// over RandomChurn without a leak. ASan's own count of bytes currently allocated by the
// program (every malloc/new in the process, not only VisSweep's; quarantine excluded) is the
// exact measure, so the bound is far tighter than the RSS one.
long LiveHeapKilobytes()
{
  return long(__sanitizer_get_current_allocated_bytes() / 1024);
}
#endif
}

// Extinction from 1e-6 to 1e9 per world unit, albedo 0 and 1, every kind of strategy.
TEST(Stress, ExtinctionScalesAndAlbedo)
{
  auto volume = DefaultBall();
  for (double albedo : { 0.0, 1.0 })
  {
    Scene s(volume);
    s.Color()->RemoveAllPoints();
    s.Color()->AddRGBPoint(0.0, albedo, albedo, albedo);
    s.Color()->AddRGBPoint(1.0, albedo, albedo, albedo);
    s.Mapper()->SetEnvironmentVisible(false);
    const double bound = MaxRadiance(s.Sky());
    for (double scale : { 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9 })
    {
      for (int strategy : kStrategies)
      {
        s.Mapper()->SetDensityScale(scale);
        s.Mapper()->SetSamplingStrategy(strategy);
        Result r = s.Render(8, bound);
        const std::string what =
          "density scale " + std::to_string(scale) + ", albedo " + std::to_string(albedo) + ", strategy " +
          std::to_string(strategy);
        ExpectSane(r, what);
        if (albedo == 0.0)
        {
          EXPECT_EQ(r.MaxMean, 0.0) << what << ": a black medium scatters no light";
        }
      }
    }
  }
}

// A dense medium converges to its opaque limit (issue 13, item 4): from an extinction of ~1e6 per
// world unit up, the soft ball is opaque wherever its scalar is positive, so the image (alpha and
// radiance, pixel by pixel) no longer depends on the density. Compared with the image at 1e6 (at
// 1e4 the ball's soft edge still lets light ~0.04 voxel deep: its coverage is 1.3% below the
// limit, which Environment and TwoStep resolve at 64 spp). At 1e9 the trackers used to take steps
// float could not add to t (the ball vanished or turned to speckles, and a frame took minutes);
// then scatter points rounded by more than light penetrates (Environment, TwoStep and Auto
// several percent dark at 1e9); at unit distances of 1e-20 and 1e-35 the ball vanished. The
// table now clamps extinction to what float resolves in the volume
// (vs::VolumeScene::MaxResolvedExtinction). Every strategy, extinction up to 1e9 (and 1e9 times
// 1e35), unit distances down to 1e-35.
TEST(Stress, DenseMediumReachesItsOpaqueLimit)
{
  auto volume = DefaultBall();
  const int spp = 64;
  for (int strategy : { vtkVisibilitySweepVolumeMapper::Uniform, vtkVisibilitySweepVolumeMapper::Environment,
         vtkVisibilitySweepVolumeMapper::TwoStep, vtkVisibilitySweepVolumeMapper::Auto })
  {
    Scene s(volume);
    s.Mapper()->SetEnvironmentVisible(false);
    s.Mapper()->SetSamplingStrategy(strategy);
    const double bound = MaxRadiance(s.Sky());
    s.Mapper()->SetDensityScale(1e6);
    const Result ref = s.Render(spp, bound);
    ExpectSane(ref, "reference (density scale 1e6)");
    EXPECT_GT(ref.Coverage, 0.25) << "the ball covers a good part of the image";
    struct Dense
    {
      const char* name;
      double scale, unitDistance;
    };
    for (const Dense& d : { Dense{ "density scale 1e9", 1e9, 1.0 }, Dense{ "density scale 1e12", 1e12, 1.0 },
           Dense{ "unit distance 1e-9", 1.0, 1e-9 }, Dense{ "unit distance 1e-20", 1.0, 1e-20 },
           Dense{ "unit distance 1e-35", 1.0, 1e-35 }, Dense{ "density scale 1e9, unit distance 1e-35", 1e9, 1e-35 } })
    {
      s.Mapper()->SetDensityScale(d.scale);
      s.Property()->SetScalarOpacityUnitDistance(d.unitDistance);
      const Result r = s.Render(spp, bound);
      const std::string what = std::string(d.name) + ", strategy " + std::to_string(strategy);
      ExpectSane(r, what);
      // Pixel by pixel, rgb and alpha agree with the reference: sum of z^2 over pixels and channels
      // ~ chi-square(4 x 256) (mean 1024, sd 45; smaller here: both images use the same seed, so their
      // noise is correlated and a systematic difference stands out); reject beyond 1024 + 6 sd.
      double chi2 = 0.0;
      int dof = 0;
      for (size_t i = 0; i < r.PixelMean.size(); ++i)
      {
        const double se2 = (r.PixelVariance[i] + ref.PixelVariance[i]) / spp;
        const double diff = r.PixelMean[i] - ref.PixelMean[i];
        if (se2 > 0.0)
        {
          chi2 += diff * diff / se2;
          ++dof;
        }
        else
        {
          EXPECT_NEAR(r.PixelMean[i], ref.PixelMean[i], 1e-6) << what << ": value " << i << " (no variance)";
        }
      }
      std::cout << what << ": chi-square " << chi2 << " for " << dof << " values, coverage " << r.Coverage << " (reference "
                << ref.Coverage << ")\n";
      EXPECT_LT(chi2, dof + 6.0 * std::sqrt(2.0 * dof)) << what << ": the image differs from the opaque limit ("
                                                       << dof << " values with variance)";
      EXPECT_NEAR(r.Coverage, ref.Coverage, 0.03) << what << ": the ball's coverage";
    }
    s.Property()->SetScalarOpacityUnitDistance(1.0);
  }
}

// Black, constant, a 1e6 dynamic-range sun, one bright texel, and a map whose importance is
// zero over whole quadtree subtrees.
TEST(Stress, HostileEnvironments)
{
  auto volume = DefaultBall();
  struct Case
  {
    const char* name;
    std::function<void(int, int, float*)> texel;
  };
  const int size = 64;
  const Case cases[] = {
    { "black", [](int, int, float* c) { c[0] = c[1] = c[2] = 0.0f; } },
    { "constant", [](int, int, float* c) { c[0] = c[1] = c[2] = 1.0f; } },
    { "sun 1e6 over sky 1", [](int x, int y, float* c) { c[0] = c[1] = c[2] = (x == 40 && y == 17) ? 1e6f : 1.0f; } },
    { "one bright texel", [](int x, int y, float* c) { c[0] = c[1] = c[2] = (x == 3 && y == 60) ? 50.0f : 0.0f; } },
    { "zero subtrees", [](int x, int y, float* c) { c[0] = c[1] = c[2] = (x < 32 || y >= 48) ? 0.0f : 1e-30f + (x == 33 ? 1.0f : 0.0f); } },
    { "1e-30 everywhere", [](int, int, float* c) { c[0] = c[1] = c[2] = 1e-30f; } },
  };
  for (const Case& c : cases)
  {
    Scene s(volume);
    auto env = MakeEnvironment(size, c.texel);
    s.Mapper()->SetEnvironmentData(env);
    const double bound = MaxRadiance(env);
    for (int strategy : kStrategies)
    {
      s.Mapper()->SetSamplingStrategy(strategy);
      Result r = s.Render(16, bound);
      ExpectSane(r, std::string(c.name) + ", strategy " + std::to_string(strategy));
      if (std::string(c.name) == "black")
      {
        EXPECT_EQ(r.MaxMean, 0.0) << "a black sky lights nothing";
      }
    }
  }
}

// Degenerate and extreme geometry.
TEST(Stress, Geometry)
{
  struct Case
  {
    const char* name;
    int nx, ny, nz;
    double spacing[3];
  };
  const Case cases[] = {
    { "1x1x1", 1, 1, 1, { 1, 1, 1 } },
    { "1x1xN", 1, 1, 9, { 1, 1, 1 } },
    { "Nx1x1", 9, 1, 1, { 1, 1, 1 } },
    { "non power of two", 7, 5, 3, { 1, 1, 1 } },
    { "spacing 1e-6", 8, 8, 8, { 1e-6, 1e-6, 1e-6 } },
    { "spacing 1e6", 8, 8, 8, { 1e6, 1e6, 1e6 } },
    { "anisotropic 1:100", 8, 8, 8, { 1, 1, 100 } },
  };
  for (const Case& c : cases)
  {
    double spacing[3] = { c.spacing[0], c.spacing[1], c.spacing[2] };
    auto volume = MakeVolume(c.nx, c.ny, c.nz, [&](int x, int y, int z) { return 0.2f + Ball(x, y, z, c.nx, c.ny, c.nz); },
      spacing);
    Scene s(volume);
    // Opacity per unit length scales with the spacing: keep the optical depth moderate.
    s.Property()->SetScalarOpacityUnitDistance(c.spacing[0]);
    // Look at the long side of thin volumes (from +z a 9 x 1 x 1 line or an 8 x 8 x 800
    // column is a speck).
    s.Renderer()->GetActiveCamera()->Elevation(60.0);
    s.Renderer()->GetActiveCamera()->OrthogonalizeViewUp();
    s.Renderer()->ResetCamera();
    const double bound = MaxRadiance(s.Sky());
    for (int strategy : kStrategies)
    {
      s.Mapper()->SetSamplingStrategy(strategy);
      Result r = s.Render(8, bound);
      ExpectSane(r, std::string(c.name) + ", strategy " + std::to_string(strategy));
      EXPECT_GT(r.Coverage, 0.01) << c.name << ": the volume must show";
    }
  }
}

// Camera inside the volume, exactly on a face, and rays exactly along axes and diagonals.
TEST(Stress, CameraPlacement)
{
  auto volume = DefaultBall(); // index = world here, box [0, 11]^3
  Scene s(volume);
  const double bound = MaxRadiance(s.Sky());
  struct Case
  {
    const char* name;
    double position[3], focal[3], up[3];
  };
  const Case cases[] = {
    { "inside", { 5.5, 5.5, 5.5 }, { 5.5, 5.5, 20 }, { 0, 1, 0 } },
    { "on a face", { 5.5, 5.5, 0.0 }, { 5.5, 5.5, 11 }, { 0, 1, 0 } },
    { "on an edge", { 0.0, 0.0, 5.5 }, { 11, 11, 5.5 }, { 0, 0, 1 } },
    { "along x", { -30, 5.5, 5.5 }, { 5.5, 5.5, 5.5 }, { 0, 0, 1 } },
    { "along -z", { 5.5, 5.5, 40 }, { 5.5, 5.5, 5.5 }, { 0, 1, 0 } },
    { "along the diagonal", { -20, -20, -20 }, { 5.5, 5.5, 5.5 }, { 0, 0, 1 } },
    { "through a corner", { -10, -10, -10 }, { 0, 0, 0 }, { 0, 0, 1 } },
  };
  for (const Case& c : cases)
  {
    vtkCamera* cam = s.Renderer()->GetActiveCamera();
    cam->SetPosition(c.position);
    cam->SetFocalPoint(c.focal);
    cam->SetViewUp(c.up);
    s.Renderer()->ResetCameraClippingRange();
    for (int parallel : { 0, 1 })
    {
      cam->SetParallelProjection(parallel);
      cam->SetParallelScale(8.0);
      Result r = s.Render(8, bound);
      ExpectSane(r, std::string(c.name) + (parallel ? ", parallel" : ", perspective"));
    }
  }
}

// NaN, +Inf, -Inf and negative voxels; constant volumes; a volume empty under the TF.
TEST(Stress, HostileData)
{
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  struct Case
  {
    const char* name;
    std::function<float(int, int, int)> f;
  };
  const Case cases[] = {
    { "NaN voxels", [&](int x, int y, int z) { return (x + y + z) % 3 == 0 ? nan : Ball(x, y, z, N, N, N); } },
    { "+Inf voxels", [&](int x, int y, int z) { return (x * y + z) % 5 == 0 ? inf : Ball(x, y, z, N, N, N); } },
    { "-Inf voxels", [&](int x, int y, int z) { return (x + 2 * y) % 4 == 0 ? -inf : Ball(x, y, z, N, N, N); } },
    { "negative voxels", [&](int x, int y, int z) { return Ball(x, y, z, N, N, N) - 0.5f; } },
    { "all NaN", [&](int, int, int) { return nan; } },
    { "constant 0.5", [&](int, int, int) { return 0.5f; } },
    { "constant 0", [&](int, int, int) { return 0.0f; } },
    { "huge values", [&](int x, int y, int z) { return 1e30f * Ball(x, y, z, N, N, N); } },
  };
  for (const Case& c : cases)
  {
    Scene s(MakeVolume(N, N, N, c.f));
    const double bound = MaxRadiance(s.Sky());
    for (int strategy : kStrategies)
    {
      s.Mapper()->SetSamplingStrategy(strategy);
      Result r = s.Render(8, bound);
      ExpectSane(r, std::string(c.name) + ", strategy " + std::to_string(strategy));
    }
  }
}

// A volume that is empty under the transfer function renders the background and skips the
// sweeps and the scattering work.
TEST(Stress, EmptyUnderTheTransferFunctionSkipsTheWork)
{
  Scene s(DefaultBall());
  s.Opacity()->RemoveAllPoints();
  s.Opacity()->AddPoint(0.0, 0.0);
  s.Opacity()->AddPoint(1.0, 0.0);
  s.Mapper()->SetSamplingStrategyToTwoStep();
  Result r = s.Render(8, MaxRadiance(s.Sky()));
  ExpectSane(r, "empty under the TF");
  EXPECT_EQ(s.Mapper()->GetVisibilityUpdateCount(), 0) << "no sweeps for an empty volume";
}

// The largest 3D image the device allows along one axis works; one voxel more is refused
// with an error that names the limit, before any allocation.
TEST(Stress, DeviceImageSizeLimit)
{
  Scene ok(MakeVolume(4096, 2, 2, [](int x, int, int) { return float(x % 16) / 15.0f; }));
  ExpectSane(ok.Render(2, MaxRadiance(ok.Sky())), "4096 x 2 x 2");
  Scene tooWide(MakeVolume(4097, 2, 2, [](int, int, int) { return 0.5f; }));
  Result r = tooWide.Render(2, 1.0);
  EXPECT_NE(r.Error.find("maxImageDimension3D"), std::string::npos) << r.Error;
}

// 100,000 samples per pixel without drift: the two halves of the run agree within their
// statistical error (Kahan-compensated float sums on the device).
TEST(Stress, LongAccumulationDoesNotDrift)
{
  Scene s(DefaultBall(), 4);
  s.Mapper()->SetSamplingStrategyToTwoStep();
  s.Mapper()->SetEnvironmentVisible(false);
  const int half = 50000;
  s.Mapper()->SetMaximumSamples(2 * half);
  s.Mapper()->SetSamplesPerFrame(half);
  s.Window()->Render();
  ASSERT_EQ(s.Mapper()->GetAccumulatedSamples(), half) << s.Mapper()->GetLastError();
  auto first = vtkSmartPointer<vtkFloatArray>::New();
  first->DeepCopy(s.Mapper()->GetRadiance(true)->GetPointData()->GetArray("Radiance"));
  auto firstVar = vtkSmartPointer<vtkDoubleArray>::New();
  firstVar->DeepCopy(s.Mapper()->GetRadiance(true)->GetPointData()->GetArray("Variance"));
  s.Window()->Render();
  ASSERT_EQ(s.Mapper()->GetAccumulatedSamples(), 2 * half);
  vtkDataArray* all = s.Mapper()->GetRadiance(true)->GetPointData()->GetArray("Radiance");
  int compared = 0;
  double worst = 0.0;
  for (vtkIdType i = 0; i < all->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double m1 = first->GetComponent(i, c), mAll = all->GetComponent(i, c);
      const double m2 = 2.0 * mAll - m1; // the second half's mean
      const double se = std::sqrt(2.0 * firstVar->GetComponent(i, c) / half);
      ASSERT_TRUE(std::isfinite(m2));
      if (se > 0.0)
      {
        worst = std::max(worst, std::abs(m1 - m2) / se);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 0);
  EXPECT_LT(worst, 5.0) << "the halves of a 100,000-sample run differ by " << worst << " standard errors";
}

// Random changes with a render after each: transfer-function points, camera, environment
// rotation (a new sun direction), strategy, clipping plane, cropping. No crash, no NaN,
// and memory does not grow once everything has been allocated once.
TEST(Stress, RandomChurn)
{
  // Mesa writes its shader disk cache from a thread of its own, compressing each new kernel some
  // time after it was compiled: with a cold cache (a clean CI machine) those allocations land in the
  // windows below at random (a clean-clone run saw +255 KB in the second window with no compile in
  // it). Without the disk cache the driver allocates only when it compiles, which the test counts.
  // Before the device exists: each test is its own process (gtest_discover_tests).
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  Scene s(DefaultBall(), 8);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  vtkNew<vtkPlane> plane;
  const double bound = 1000.0; // the sun's radiance (sky 0)
  long rssAfterWarmup = 0;
  // Compile every kernel the changes can reach first (one per strategy, cell mode and cell walk,
  // kept for the process; lavapipe compiles, and Mesa writes its disk cache in the background,
  // at a kernel's first dispatch): one-time costs that random changes would otherwise reach at
  // random times, inside a measurement window (issue 13, item 11: the test failed in one run in
  // four, always one with a new kernel in its second window).
  s.Mapper()->SetCroppingRegionPlanes(0, 11, 0, 11, 0, 11);
  for (bool cropping : { false, true }) // cropping regions have their own kernels too
  {
    s.Mapper()->SetCropping(cropping);
    for (double density : { 1.0, 1e6 })
    {
      s.Mapper()->SetDensityScale(density); // 1e6: optically thick bricks, the cell walk's kernel
      for (int strategy = 0; strategy <= vtkVisibilitySweepVolumeMapper::Auto; ++strategy)
      {
        for (int cellMode : { 0, 1 })
        {
          s.Mapper()->SetSamplingStrategy(strategy);
          s.Mapper()->SetCellMode(cellMode);
          ASSERT_EQ(s.Render(1, bound).Error, "");
        }
      }
    }
  }
  s.Mapper()->SetCropping(false);
  s.Mapper()->SetDensityScale(1.0);
  // Heap growth over the changes of each window that compiled no new pipeline (should be all:
  // the count says), so that a kernel the warm-up missed cannot pass for a leak.
  long window[2] = { 0, 0 };
  int compiles[2] = { 0, 0 };
  const int changes = 1000;
  long heapBefore = LiveHeapKilobytes();
  for (int i = 0; i < changes; ++i)
  {
    switch (int(U(rng) * 7))
    {
      case 0:
        s.Opacity()->AddPoint(U(rng), U(rng));
        break;
      case 1:
        s.Renderer()->GetActiveCamera()->Azimuth(360.0 * U(rng));
        s.Renderer()->GetActiveCamera()->Elevation(40.0 * U(rng) - 20.0);
        s.Renderer()->GetActiveCamera()->OrthogonalizeViewUp();
        break;
      case 2:
        s.Sky()->SetSunDirection(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
        break;
      case 3:
        s.Mapper()->SetSamplingStrategy(int(U(rng) * 5));
        break;
      case 4:
        s.Mapper()->RemoveAllClippingPlanes();
        if (U(rng) < 0.5)
        {
          plane->SetOrigin(11 * U(rng), 11 * U(rng), 11 * U(rng));
          plane->SetNormal(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
          s.Mapper()->AddClippingPlane(plane);
        }
        break;
      case 5:
        s.Mapper()->SetCropping(U(rng) < 0.5);
        s.Mapper()->SetCroppingRegionPlanes(0, 11 * U(rng), 0, 11, 11 * U(rng), 11);
        break;
      default:
        s.Mapper()->SetCellMode(int(U(rng) * 2));
        break;
    }
    if (s.Opacity()->GetSize() > 12)
    {
      s.Opacity()->RemoveAllPoints();
      s.Opacity()->AddPoint(0.0, 0.0);
      s.Opacity()->AddPoint(1.0, 0.8);
    }
    s.Renderer()->ResetCameraClippingRange();
    const uint64_t pipelinesBefore = vs::Context::Default()->PipelineBuilds(); // compiles, also those that let another go
    Result r = s.Render(1, bound);
    ASSERT_EQ(r.Error, "") << "change " << i;
    ASSERT_EQ(r.NonFinite, 0) << "change " << i;
    if (i == 100)
    {
      rssAfterWarmup = ResidentKilobytes();
    }
    const long heapNow = LiveHeapKilobytes();
    if (i > 100)
    {
      // The change and its render, from the end of the last one.
      const int w = i <= 550 ? 0 : 1;
      if (vs::Context::Default()->PipelineBuilds() == pipelinesBefore)
        window[w] += heapNow - heapBefore;
      else
        ++compiles[w];
    }
    heapBefore = heapNow;
  }
  // Two windows of 450 changes: a leak grows the heap in both, a one-time cost (a new malloc
  // arena of a lavapipe worker, a driver cache filling up) in one. Renders that compiled a
  // pipeline are left out (the kernel has one per strategy, cell mode and cell walk, kept for the
  // process, which random changes reach at random times; one is ~100-300 KB). The bound on the
  // smaller window keeps the leak sensitivity of the old single bound (256 KB over 900 changes,
  // i.e. 128 KB per window: a 1 KB leak per change reads ~450 KB in each).
  auto windows = [&]() {
    std::cout << "live heap grew by " << window[0] << " KB, then " << window[1] << " KB (two windows of "
              << (changes - 100) / 2 << " changes, without the " << compiles[0] << " and " << compiles[1]
              << " renders that compiled a pipeline)\n";
    return std::min(window[0], window[1]);
  };
#if VS_STRESS_ASAN
  const long heapGrowth = windows();
  std::cout << "(ASan count; resident memory grew by " << ResidentKilobytes() - rssAfterWarmup
            << " KB: ASan's quarantine and allocator, not checked)\n";
  EXPECT_LT(heapGrowth, 128) << "the heap grows in both windows of changes (leak?)";
#else
  const long heapGrowth = windows();
  std::cout << "(mallinfo2; resident memory grew by " << ResidentKilobytes() - rssAfterWarmup << " KB, not checked)\n";
  EXPECT_LT(heapGrowth, 128) << "the heap grows in both windows of changes (leak?)";
#endif
}
