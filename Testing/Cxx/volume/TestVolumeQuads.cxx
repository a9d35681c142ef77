// An integer-coded volume's 8-bit quads (vsDeviceVolume.h): which volumes get them, their packing,
// and that the render kernel's trilinear samples from them are the same floats as from the r32f
// image: the same image bit for bit, with and without them.
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsRenderTestScene.h"

#include "sampling/strategies.h"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(VolumeQuads, RenderIsBitIdenticalToTheFloatImage)
{
  // Integer scalars 10..13 (offset 10), a few empty voxels; linear interpolation.
  RenderScene scene({ { 21, 18, 15 } },
    [](int x, int y, int z) { return (x + y + z) % 7 == 0 ? 0.0f : float(10 + (x * 3 + y * 5 + z) % 4); }, 0.05,
    glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 2, 3)), 5.0, glm::vec3(40.0f), glm::vec3(0.3f)));
  ASSERT_NE(scene.Volume->Quads(), nullptr) << "the scene's volume is integer-coded";
  for (uint32_t strategy : { vs::shared::VS_STRATEGY_ENVIRONMENT, vs::shared::VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(10, 10, -3.0f, 24.0f, strategy, 64, 23u, true);
    scene.VolumeQuads = false;
    auto [a, va] = scene.Render(p, 2);
    EXPECT_FALSE(scene.LastUsedVolumeQuads);
    scene.VolumeQuads = true;
    auto [b, vb] = scene.Render(p, 2);
    EXPECT_TRUE(scene.LastUsedVolumeQuads);
    EXPECT_EQ(a, b) << "strategy " << strategy;
    EXPECT_EQ(va, vb) << "strategy " << strategy;
    double sum = 0.0;
    for (float x : a)
      sum += x;
    EXPECT_GT(sum, 0.0) << "an image, not zeros";
  }
}
