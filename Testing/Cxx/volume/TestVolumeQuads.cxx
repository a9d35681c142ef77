// An integer-coded volume's 8-bit quads (vsDeviceVolume.h): which volumes get them, their packing,
// and that the render kernel's trilinear samples from them are the same floats as from the r32f
// image: the same image bit for bit, with and without them. The float image of such a volume is made
// from its quads only when a pass reads floats: the render kernel and the sweeps' pool never do.
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsPooledExtinction.h"
#include "vsRenderTestScene.h"
#include "vsTransferFunctionTable.h"

#include "sampling/strategies.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using vstest::RenderScene;

TEST(VolumeQuads, OnlyForFiniteIntegersWithin255OfTheSmallest)
{
  auto ctx = vs::Context::Default();
  const std::array<uint32_t, 3> dims{ { 5, 4, 3 } };
  std::vector<float> v(60);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = float(int(i * 37 % 256)) - 100.0f; // integers in [-100, 155]
  {
    vs::DeviceVolume volume(ctx, v.data(), dims);
    ASSERT_NE(volume.Quads(), nullptr);
    EXPECT_EQ(volume.QuadOffset(), -100.0f);
    std::vector<uint32_t> q(60);
    volume.Quads()->Download(q.data(), q.size() * 4);
    auto code = [&](uint32_t x, uint32_t y, uint32_t z) { return uint32_t(v[(z * 4 + y) * 5 + x] + 100.0f); };
    for (uint32_t z = 0; z < 3; ++z)
      for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 5; ++x)
        {
          const uint32_t x1 = std::min(x + 1, 4u), y1 = std::min(y + 1, 3u);
          EXPECT_EQ(q[(z * 4 + y) * 5 + x],
            code(x, y, z) | code(x1, y, z) << 8 | code(x, y1, z) << 16 | code(x1, y1, z) << 24)
            << x << " " << y << " " << z;
        }
  }
  auto without = [&](std::vector<float> w, const char* why) {
    vs::DeviceVolume volume(ctx, w.data(), dims);
    EXPECT_EQ(volume.Quads(), nullptr) << why;
  };
  std::vector<float> w = v;
  w[7] = 156.0f + 100.0f; // spans 356
  without(w, "a span over 255");
  w = v;
  w[3] = 0.5f;
  without(w, "a fraction");
  w = v;
  w[11] = std::nanf("");
  without(w, "a NaN voxel");
  w = v;
  w[0] = INFINITY;
  without(w, "an infinite voxel");
}

TEST(VolumeQuads, TheFloatImageIsMadeFromTheQuadsOnlyWhenAsked)
{
  auto ctx = vs::Context::Default();
  const std::array<uint32_t, 3> dims{ { 13, 9, 5 } };
  std::vector<float> v(size_t(dims[0]) * dims[1] * dims[2]);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = float(int(i * 37 % 256)) - 100.0f; // integers in [-100, 155]
  vs::DeviceVolume coded(ctx, v.data(), dims);
  ASSERT_NE(coded.Quads(), nullptr);
  EXPECT_FALSE(coded.HasImage()) << "an integer-coded volume holds its quads alone until a pass reads floats";
  std::vector<float> floats(v.size());
  coded.Image().Download(floats.data(), floats.size() * sizeof(float));
  EXPECT_TRUE(coded.HasImage());
  EXPECT_EQ(floats, v) << "the same floats as uploaded";

  std::vector<float> w = v;
  w[3] = 0.5f; // not integer-coded: the float image from the start
  vs::DeviceVolume plain(ctx, w.data(), dims);
  EXPECT_EQ(plain.Quads(), nullptr);
  EXPECT_TRUE(plain.HasImage());
  plain.Image().Download(floats.data(), floats.size() * sizeof(float));
  EXPECT_EQ(floats, w);
}

// The sweeps' pool of an integer-coded volume reads the quads: the same pooled extinction bit for bit
// as from the float image, which the pool never asks for (the majorants from the host's scalars, as
// the mapper makes them).
TEST(VolumeQuads, PoolFromTheQuadsIsTheFloatImagesBitForBit)
{
  auto ctx = vs::Context::Default();
  const std::array<uint32_t, 3> dims{ { 19, 14, 11 } }; // odd: blocks past the end clamp
  std::vector<float> v(size_t(dims[0]) * dims[1] * dims[2]);
  for (uint32_t z = 0; z < dims[2]; ++z)
    for (uint32_t y = 0; y < dims[1]; ++y)
      for (uint32_t x = 0; x < dims[0]; ++x)
        v[(size_t(z) * dims[1] + y) * dims[0] + x] = (x + y + z) % 5 == 0 ? 3.0f : float(3 + (x * 7 + y * 3 + z) % 200);
  auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 255.0f, 256,
    [](double s) { return std::min(0.9, s / 255.0); }, [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0,
    1.0);
  vs::TransferFunctionTable tf(ctx, samples);
  const auto download = [](const vs::Image3D& image) {
    std::vector<float> out(image.Bytes() / sizeof(float));
    image.Download(out.data(), image.Bytes());
    return out;
  };
  for (bool max : { false, true })
  {
    vs::DeviceVolume volume(ctx, v.data(), dims);
    ASSERT_NE(volume.Quads(), nullptr);
    vs::MajorantGrid majorants(ctx);
    majorants.UpdateRanges(volume, v.data());
    majorants.UpdateMajorants(samples);
    vs::PooledExtinction::Settings settings;
    settings.Factor = 2;
    settings.Max = max;
    vs::PooledExtinction fromQuads(ctx);
    EXPECT_GT(fromQuads.Ensure(volume, tf, majorants, settings), 0.0);
    EXPECT_FALSE(volume.HasImage()) << "the pool read the quads alone";
    vs::PooledExtinction fromFloats(ctx);
    fromFloats.SetVolumeQuads(false);
    EXPECT_GT(fromFloats.Ensure(volume, tf, majorants, settings), 0.0);
    EXPECT_TRUE(volume.HasImage());
    const std::vector<float> a = download(fromQuads.Pooled()), b = download(fromFloats.Pooled());
    EXPECT_EQ(a, b) << (max ? "max" : "mean") << " pooling";
    double sum = 0.0;
    for (float e : a)
      sum += e;
    EXPECT_GT(sum, 0.0) << "extinction, not zeros";
    EXPECT_EQ(download(fromQuads.Occupancy()), download(fromFloats.Occupancy()));
  }
}

TEST(VolumeQuads, RenderIsBitIdenticalToTheFloatImage)
{
  // Integer scalars 10..13 (offset 10), a few empty voxels; linear interpolation.
  const auto scalar = [](int x, int y, int z) {
    return (x + y + z) % 7 == 0 ? 0.0f : float(10 + (x * 3 + y * 5 + z) % 4);
  };
  const std::array<uint32_t, 3> dims{ { 21, 18, 15 } };
  RenderScene scene(dims, scalar, 0.05, glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 2, 3)), 5.0, glm::vec3(40.0f), glm::vec3(0.3f)));
  ASSERT_NE(scene.Volume->Quads(), nullptr) << "the scene's volume is integer-coded";
  // The scene's grid and majorants read the float image; a fresh upload of the same scalars has none.
  std::vector<float> v(size_t(dims[0]) * dims[1] * dims[2]);
  for (uint32_t z = 0; z < dims[2]; ++z)
    for (uint32_t y = 0; y < dims[1]; ++y)
      for (uint32_t x = 0; x < dims[0]; ++x)
        v[(size_t(z) * dims[1] + y) * dims[0] + x] = scalar(int(x), int(y), int(z));
  // Variants: the brick walk; the cell walk (every majorant segment past an optical depth of 0.01,
  // whose cell corners the kernel reads); the surface lobe at every event (its normal is the
  // scalar's central differences), under full transport.
  enum Variant
  {
    Bricks,
    CellWalk,
    Surface
  };
  for (Variant variant : { Bricks, CellWalk, Surface })
    for (uint32_t strategy : { vs::shared::VS_STRATEGY_ENVIRONMENT, vs::shared::VS_STRATEGY_TWO_STEP })
    {
      auto p = scene.Params(10, 10, -3.0f, 24.0f, strategy, 64, 23u, true);
      if (variant == CellWalk)
        p.cellWalkDepth = 0.01f;
      if (variant == Surface)
      {
        p.surface = 1u;
        p.surfaceBlending = 0.0f;
        p.surfaceDiffuse = 0.6f;
        p.surfaceSpecular = 0.3f;
        p.surfaceRoughness = 0.2f;
        p.gradientScale = 4.0f;
        p.opacityDistance = 1.0f;
        p.maxEvents = 4u;
      }
      scene.Volume = std::make_unique<vs::DeviceVolume>(scene.Context, v.data(), dims);
      scene.VolumeQuads = true;
      auto [b, vb] = scene.Render(p, 2);
      EXPECT_TRUE(scene.LastUsedVolumeQuads);
      EXPECT_FALSE(scene.Volume->HasImage()) << "the kernel read the quads alone: variant " << variant;
      scene.VolumeQuads = false;
      auto [a, va] = scene.Render(p, 2);
      EXPECT_FALSE(scene.LastUsedVolumeQuads);
      EXPECT_EQ(a, b) << "variant " << variant << ", strategy " << strategy;
      EXPECT_EQ(va, vb) << "variant " << variant << ", strategy " << strategy;
      double sum = 0.0;
      for (float x : a)
        sum += x;
      EXPECT_GT(sum, 0.0) << "an image, not zeros";
    }
}

// The upload's slabs run on the host's threads, each faulting its share of the image's memory in first
// (vsDeviceVolume.cxx). That share is a range of bytes, not of slices: the memory's layout is the
// driver's. Faulting in by a write, a slab that started late once zeroed a byte of each page of a
// neighbour's slices that were already uploaded (the voxel at each page's start of ch2 read as the
// smallest value in some runs: the preview's light volume differed between runs). Every voxel must
// arrive whatever the slabs' timing: eight slabs on this machine's cores, several uploads.
TEST(VolumeQuads, EveryVoxelArrivesWhateverTheSlabsTiming)
{
  auto ctx = vs::Context::Default();
  const char* before = std::getenv("VISSWEEP_HOST_THREADS");
  const std::string saved = before ? before : "";
  ::setenv("VISSWEEP_HOST_THREADS", "8", 1);
  const std::array<uint32_t, 3> dims{ { 192, 160, 101 } }; // 101 slices: the slabs split no page boundary evenly
  std::vector<float> v(size_t(dims[0]) * dims[1] * dims[2]);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = float(int((i * 2654435761u >> 7) % 255) + 1); // integers in [1, 255]: a zeroed code reads 0
  std::vector<float> w = v;
  for (float& x : w)
    x += 0.25f; // not integer-coded: the float image is what is uploaded
  for (int round = 0; round < 8; ++round)
  {
    const std::vector<float>& in = round % 2 == 0 ? v : w;
    vs::DeviceVolume volume(ctx, in.data(), dims);
    ASSERT_EQ(volume.Quads() != nullptr, round % 2 == 0);
    std::vector<float> floats(in.size());
    volume.Image().Download(floats.data(), floats.size() * sizeof(float));
    size_t wrong = 0;
    for (size_t i = 0; i < in.size(); ++i)
      wrong += floats[i] != in[i] ? 1 : 0;
    EXPECT_EQ(wrong, 0u) << (round % 2 == 0 ? "the quads, " : "the floats, ") << "round " << round;
  }
  if (before)
    ::setenv("VISSWEEP_HOST_THREADS", saved.c_str(), 1);
  else
    ::unsetenv("VISSWEEP_HOST_THREADS");
}
