// The sweeps' own machinery (von Radziewsky et al. 2017, Sec. 6 and 8) against the full-resolution
// and untruncated marches it replaces: the pooled extinction volume (its cache and slab-by-slab
// builds), nearest interpolation, early termination, the filter's kernel taps and the occupied box.
#include "vsVisibilityTestScene.h"

#include "vsError.h"
#include "vsImage.h"
#include "vsSweepPlan.h"
#include "vsVolumeScene.h"

#include "vtkImageData.h"
#include "vtkImageShrink3D.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using vs::VisibilityGridParameters;
using vstest::VisibilityScene;

namespace
{
// A smooth, uneven blob: a ball of density rising towards its centre, with a denser slab.
float Blob(int x, int y, int z)
{
  const double r = std::sqrt(double((x - 16) * (x - 16) + (y - 14) * (y - 14) + (z - 17) * (z - 17)));
  const double ball = std::max(0.0, 1.0 - r / 13.0);
  return float(std::min(1.0, ball + ((x / 3) % 4 == 0 && r < 13.0 ? 0.5 : 0.0)));
}

double MeanAbsDiff(const std::vector<float>& a, const std::vector<float>& b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    sum += std::abs(double(a[i]) - double(b[i]));
  return sum / double(std::max<size_t>(a.size(), 1));
}
}

// The pooled extinction volume (mean of sigma_t over P^3 voxels) against the full-resolution march:
// optical depth is linear in sigma_t, so the mean keeps it through each block; only detail inside
// a block is lost. Max pooling is conservative: never brighter on average.
TEST(VisibilityGrid, PooledSweepAgreesWithFullResolution)
{
  VisibilityScene scene({ { 33, 29, 35 } }, Blob, 0.4);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.ExtinctionPooling = 1;
  vs::VisibilityGrid full(scene.Context);
  const std::vector<float> reference = scene.Grid(full, p);
  EXPECT_EQ(full.PoolBuilds(), 0u) << "full resolution needs no pooled volume";
  for (uint32_t factor : { 2u, 4u })
  {
    p.ExtinctionPooling = factor;
    p.MaxPooling = false;
    vs::VisibilityGrid mean(scene.Context);
    const std::vector<float> pooled = scene.Grid(mean, p);
    EXPECT_EQ(mean.PoolBuilds(), 1u);
    p.MaxPooling = true;
    vs::VisibilityGrid max(scene.Context);
    const std::vector<float> darker = scene.Grid(max, p);
    const double e = MeanAbsDiff(pooled, reference), em = MeanAbsDiff(darker, reference);
    double sumMean = 0.0, sumMax = 0.0, sumRef = 0.0;
    for (size_t i = 0; i < pooled.size(); ++i)
    {
      sumMean += pooled[i];
      sumMax += darker[i];
      sumRef += reference[i];
    }
    std::printf("pooling %u: mean |dV| against full resolution %.4f (max pooling %.4f); mean V %.4f, max-pooled %.4f, "
                "full %.4f\n",
      factor, e, em, sumMean / pooled.size(), sumMax / pooled.size(), sumRef / pooled.size());
    EXPECT_GT(e, 0.0) << "pooling must change something for this test to mean anything";
    // Measured: 0.0092 at P = 2, 0.032 at P = 4 (8 pooled texels across this small volume).
    EXPECT_LT(e, factor == 2 ? 0.015 : 0.045);
    EXPECT_LE(sumMax, sumMean);
  }
}

// The pooled volume is built once per volume / transfer function and reused by later calls
// (small subsets of directions, new clip planes); a new transfer function rebuilds it, and the
// result is then what a fresh grid computes.
TEST(VisibilityGrid, PooledVolumeIsCachedAcrossCalls)
{
  VisibilityScene scene({ { 25, 25, 25 } }, Blob, 0.4);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.ExtinctionPooling = 2;
  vs::VisibilityGrid grid(scene.Context);
  const std::vector<float> all = scene.Grid(grid, p);
  for (uint32_t n : { 0u, 5u, 63u })
  {
    grid.Compute(*scene.Volume, *scene.TF, *scene.Majorants, scene.Geometry, {}, p, { n });
  }
  grid.Compute(*scene.Volume, *scene.TF, *scene.Majorants, scene.Geometry, { glm::dvec4(1.0, 0.0, 0.0, -5.0) }, p);
  grid.Compute(*scene.Volume, *scene.TF, *scene.Majorants, scene.Geometry, {}, p);
  EXPECT_EQ(grid.PoolBuilds(), 1u);
  EXPECT_EQ(grid.Download(), all) << "the cached pooled volume gives the same grid";

  // A denser transfer function over the same volume object.
  auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 1025,
    [](double s) { return 1.0 - std::exp(-s * 1.5); }, [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0,
    1.0);
  scene.TF = std::make_unique<vs::TransferFunctionTable>(scene.Context, samples);
  scene.Majorants->UpdateMajorants(samples);
  const std::vector<float> denser = scene.Grid(grid, p);
  EXPECT_EQ(grid.PoolBuilds(), 2u);
  vs::VisibilityGrid fresh(scene.Context);
  EXPECT_EQ(scene.Grid(fresh, p), denser);
  EXPECT_NE(denser, all);
}

// Nearest interpolation (a vtkVolumeProperty's default) in the sweeps and the brute force: a
// label map of stripes of the scalars 0 and 1 under a transfer function that is opaque only at
// 0.5 is transparent when each point reads its nearest voxel (V = 1 everywhere, full resolution,
// pooled or brute force), and dark under trilinear interpolation, which passes through 0.5 between
// every pair of stripes.
TEST(VisibilityGrid, NearestInterpolationSeesNoBlendedLabels)
{
  VisibilityScene scene({ { 20, 18, 17 } }, [](int x, int y, int) { return float((x / 2 + y / 3) % 2); }, 1.0);
  scene.UseHatTransferFunction(3.0);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.NearestInterpolation = true;
  for (uint32_t pooling : { 1u, 2u })
  {
    p.ExtinctionPooling = pooling;
    vs::VisibilityGrid grid(scene.Context);
    const std::vector<float> v = scene.Grid(grid, p);
    EXPECT_EQ(*std::min_element(v.begin(), v.end()), 1.0f) << "sweep, pooling " << pooling;
  }
  p.Algorithm = VisibilityGridParameters::Method::BruteForce;
  p.BruteForceSamples = 2;
  vs::VisibilityGrid brute(scene.Context);
  const std::vector<float> vb = scene.Grid(brute, p);
  EXPECT_EQ(*std::min_element(vb.begin(), vb.end()), 1.0f) << "brute force";

  // Trilinear (as before): the blended labels between the stripes occlude.
  p.NearestInterpolation = false;
  p.Algorithm = VisibilityGridParameters::Method::Sweep;
  p.ExtinctionPooling = 1;
  vs::VisibilityGrid linear(scene.Context);
  const std::vector<float> vl = scene.Grid(linear, p);
  double mean = 0.0;
  for (float x : vl)
  {
    mean += x;
  }
  mean /= double(vl.size());
  std::printf("stripes of labels 0 and 1, opaque at 0.5: mean V %.4f trilinear, 1 nearest\n", mean);
  EXPECT_LT(mean, 0.5);
}

// Kernel rays stop marching once their transmittance is below StopTransmittance and keep that
// value: against rays that march to the end (StopTransmittance 0), the grid is never darker and
// brighter by less than the threshold (the filter and the projection average kernel values, so
// they keep both bounds), and only where V is that small.
TEST(VisibilityGrid, EarlyTerminatedRaysAgreeWithUntruncatedOnes)
{
  VisibilityScene scene({ { 33, 29, 35 } }, Blob, 3.0);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  for (uint32_t pooling : { 1u, 2u })
  {
    p.ExtinctionPooling = pooling;
    p.StopTransmittance = 0.0f;
    vs::VisibilityGrid full(scene.Context);
    const std::vector<float> reference = scene.Grid(full, p);
    const float stop = VisibilityGridParameters().StopTransmittance;
    p.StopTransmittance = stop;
    vs::VisibilityGrid stopped(scene.Context);
    const std::vector<float> v = scene.Grid(stopped, p);
    ASSERT_EQ(v.size(), reference.size());
    double worst = 0.0, lowest = 0.0;
    size_t dark = 0, changed = 0;
    for (size_t i = 0; i < v.size(); ++i)
    {
      const double e = double(v[i]) - double(reference[i]);
      worst = std::max(worst, e);
      lowest = std::min(lowest, e);
      dark += reference[i] < stop ? 1 : 0;
      changed += e != 0.0 ? 1 : 0;
    }
    std::printf("pooling %u, stop at %.0e: %zu of %zu entries below it untruncated, %zu changed, dV in [%.2e, %.2e]\n",
      pooling, double(stop), dark, v.size(), changed, lowest, worst);
    EXPECT_GT(dark, v.size() / 20) << "the scene must be dense enough for rays to stop";
    EXPECT_GT(changed, 0u) << "stopping must change something for this test to mean anything";
    EXPECT_GE(lowest, -1e-6) << "a stopped ray keeps a value at least the untruncated one";
    EXPECT_LE(worst, double(stop) + 1e-6);
  }
}

namespace
{
// The old two-step form of the sweep-space filter and the projection's read along one axis: a box
// filter of every kernel ray by prefix sums (ray j covering [j, j + 1), its box [j + 0.5 - w/2,
// j + 0.5 + w/2] cut to [0, n], none for w <= 1), then the linear read at u clamped to the line.
double FilterThenRead(const std::vector<double>& k, double width, double u)
{
  const int n = int(k.size());
  std::vector<double> f = k;
  if (width > 1.0)
  {
    std::vector<double> prefix(n);
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
      prefix[j] = sum += k[j];
    auto integral = [&](double x) {
      x = std::clamp(x, 0.0, double(n));
      const int j = std::min(int(std::floor(x)), n - 1);
      const double before = j == 0 ? 0.0 : prefix[j - 1];
      return before + (x - j) * (prefix[j] - before);
    };
    for (int j = 0; j < n; ++j)
    {
      const double lo = std::max(j + 0.5 - 0.5 * width, 0.0), hi = std::min(j + 0.5 + 0.5 * width, double(n));
      f[j] = (integral(hi) - integral(lo)) / (hi - lo);
    }
  }
  const int x0 = int(std::floor(u));
  const double fx = u - x0;
  auto at = [&](int x) { return f[std::clamp(x, 0, n - 1)]; };
  return (1.0 - fx) * at(x0) + fx * at(x0 + 1);
}
}

// The sweeps filter and read the kernel in one set of weights per axis (vs_kernel_taps): the same
// as the old filter passes followed by the linear read, and no ray outside first..last weighs.
TEST(VisibilityGrid, KernelTapsAreTheFilterThenTheLinearRead)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const uint32_t n = 2 + uint32_t(uniform(rng) * 40.0);
    std::vector<double> k(n);
    for (double& x : k)
      x = uniform(rng);
    const double width = trial % 5 == 0 ? uniform(rng) : 1.0 + uniform(rng) * 12.0;
    const double u = -2.0 + uniform(rng) * (n + 3.0);
    const vs::shared::VsKernelTaps w = vs::shared::vs_kernel_taps(float(u), n, float(width));
    ASSERT_GE(w.first, 0);
    ASSERT_LE(w.last, int(n) - 1);
    double sum = 0.0, weights = 0.0;
    for (int i = 0; i < int(n); ++i)
    {
      const double weight = vs::shared::vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, i);
      if (i < w.first || i > w.last)
        ASSERT_EQ(weight, 0.0) << "ray " << i << " outside " << w.first << ".." << w.last;
      sum += weight * k[i];
      weights += weight;
    }
    EXPECT_NEAR(weights, 1.0, 1e-5);
    worst = std::max(worst, std::abs(sum / weights - FilterThenRead(k, width, u)));
    // The host's bound on the taps (the shaders unroll that many) holds.
    const int taps = w.last - w.first + 1;
    EXPECT_LE(taps, int(std::ceil(std::max(width, 1.0) * (1.0 + 1e-6))) + 2) << "width " << width;
  }
  std::printf("largest difference from the two-step filter and read: %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

// The march starts and ends each kernel ray at the occupied box (the bricks of nonzero majorant,
// widened by the pooled texels' reach) instead of the volume's box: a dense block in a corner of a
// mostly empty volume casts the same shadow as the brute force (which marches the whole box) sees.
TEST(VisibilityGrid, OccupiedBoxKeepsTheShadowOfAnIsolatedBlock)
{
  VisibilityScene scene({ { 40, 36, 44 } },
    [](int x, int y, int z) { return x >= 25 && x <= 32 && y >= 4 && y <= 10 && z >= 27 && z <= 35 ? 1.0f : 0.0f; },
    0.4);
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.Algorithm = VisibilityGridParameters::Method::BruteForce;
  p.BruteForceSamples = 16;
  vs::VisibilityGrid brute(scene.Context);
  const std::vector<float> reference = scene.Grid(brute, p);
  size_t shadowed = 0;
  for (float v : reference)
    shadowed += v < 0.5f ? 1 : 0;
  EXPECT_GT(shadowed, reference.size() / 100) << "the block must shadow part of the grid for this test to mean anything";
  p.Algorithm = VisibilityGridParameters::Method::Sweep;
  for (uint32_t pooling : { 1u, 2u })
  {
    p.ExtinctionPooling = pooling;
    vs::VisibilityGrid sweep(scene.Context);
    const std::vector<float> v = scene.Grid(sweep, p);
    double sumSweep = 0.0, sumBrute = 0.0;
    for (size_t i = 0; i < v.size(); ++i)
    {
      sumSweep += 1.0 - v[i];
      sumBrute += 1.0 - reference[i];
    }
    const double e = MeanAbsDiff(v, reference);
    std::printf("isolated block, pooling %u: mean |dV| against the brute force %.4f; shadow (sum of 1 - V) %.1f "
                "against %.1f\n",
      pooling, e, sumSweep, sumBrute);
    // Measured: mean |dV| 0.0089 (P = 1) and 0.0098 (P = 2); shadow ratio 1.004 and 1.145 (mean pooling
    // spreads the block's edges over a pooled texel, so grazing rays gain optical depth). A ray cut short
    // by the occupied box would lose shadow: the ratio would fall below 1.
    EXPECT_LT(e, 0.02);
    EXPECT_GT(sumSweep / sumBrute, 0.98);
    EXPECT_LT(sumSweep / sumBrute, pooling == 1 ? 1.03 : 1.25);
  }
}

// The pooled extinction built slab by slab within a budget (progressive grids: no frame waits for
// the whole build) is the one built at once, bit for bit, and so is the grid swept over it. The
// first slab is built whatever the budget (to learn its cost); after it a budget below a slab's
// cost builds nothing (a progressive grid's share of the time stays its share), a large one the
// rest; the volume is not current until the last slab.
TEST(VisibilityGrid, PooledVolumeBuiltInSlabsIsTheWholeBuild)
{
  VisibilityScene scene({ { 25, 25, 40 } }, Blob, 0.4);
  vs::PooledExtinction::Settings settings;
  settings.Factor = 2; // 20 pooled slices: 5 slabs
  vs::PooledExtinction whole(scene.Context);
  EXPECT_GT(whole.Ensure(*scene.Volume, *scene.TF, *scene.Majorants, settings), 0.0);
  EXPECT_TRUE(whole.IsCurrent(*scene.Volume, *scene.TF, *scene.Majorants, settings));
  EXPECT_EQ(whole.Ensure(*scene.Volume, *scene.TF, *scene.Majorants, settings), 0.0) << "cached";

  vs::PooledExtinction slabs(scene.Context);
  EXPECT_GT(slabs.Advance(*scene.Volume, *scene.TF, *scene.Majorants, settings, 1e-12), 0.0) << "the first slab";
  for (int call = 0; call < 3; ++call)
  {
    EXPECT_FALSE(slabs.IsCurrent(*scene.Volume, *scene.TF, *scene.Majorants, settings));
    EXPECT_EQ(slabs.Advance(*scene.Volume, *scene.TF, *scene.Majorants, settings, 1e-12), 0.0)
      << "a budget below a slab's cost builds nothing";
  }
  EXPECT_FALSE(slabs.IsCurrent(*scene.Volume, *scene.TF, *scene.Majorants, settings));
  EXPECT_EQ(slabs.Builds(), 0u);
  EXPECT_GT(slabs.Advance(*scene.Volume, *scene.TF, *scene.Majorants, settings, 1e9), 0.0) << "the other four slabs";
  EXPECT_TRUE(slabs.IsCurrent(*scene.Volume, *scene.TF, *scene.Majorants, settings));
  EXPECT_EQ(slabs.Builds(), 1u);
  const auto download = [](const vs::Image3D& image) {
    std::vector<float> v(image.Bytes() / sizeof(float));
    image.Download(v.data(), image.Bytes());
    return v;
  };
  EXPECT_EQ(download(slabs.Pooled()), download(whole.Pooled()));
  EXPECT_EQ(download(slabs.Occupancy()), download(whole.Occupancy()));

  // New inputs restart a build: a denser transfer function is not current until rebuilt.
  auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 1025,
    [](double s) { return 1.0 - std::exp(-s * 1.5); }, [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0,
    1.0);
  vs::TransferFunctionTable denser(scene.Context, samples);
  scene.Majorants->UpdateMajorants(samples);
  EXPECT_FALSE(slabs.IsCurrent(*scene.Volume, denser, *scene.Majorants, settings));

  // The grid: slabs through AdvancePool, then a sweep that finds the pool current.
  scene.Majorants->UpdateMajorants(scene.TF->Samples());
  VisibilityGridParameters p;
  p.StorageFormat = VisibilityGridParameters::Format::Float32;
  p.ExtinctionPooling = 2;
  vs::VisibilityGrid reference(scene.Context);
  const std::vector<float> all = scene.Grid(reference, p);
  vs::VisibilityGrid grid(scene.Context);
  grid.Allocate(scene.Geometry, p);
  bool ready = false;
  grid.AdvancePool(*scene.Volume, *scene.TF, *scene.Majorants, 1e-12, ready);
  EXPECT_FALSE(ready);
  grid.AdvancePool(*scene.Volume, *scene.TF, *scene.Majorants, 1e9, ready);
  ASSERT_TRUE(ready);
  EXPECT_EQ(grid.PoolBuilds(), 1u);
  EXPECT_EQ(scene.Grid(grid, p), all);
  EXPECT_EQ(grid.PoolBuilds(), 1u) << "the sweep used the pool built in slabs";
}
