// The grid strategies' direction table on the device (vsDirectionTable.h): the
// table the device builds is the one the shared header packs on the CPU from
// the same grid and light, it is rebuilt exactly when what it depends on
// changes, and rendering from it is unbiased (its image agrees with the map
// built at every scatter event, within the standard errors).
#include "vsRenderTestScene.h"

#include "sampling/direction_table.h"
#include "sampling/strategies.h"
#include "vsBuffer.h"
#include "vsDirectionTable.h"
#include "vsError.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace vs::shared;
using vstest::RenderScene;

namespace
{
RenderScene MakeScene()
{
  return RenderScene(
    { { 17, 15, 13 } }, [](int x, int y, int z) { return float((x * 7 + y * 3 + z * 5) % 11) / 10.0f * float(x > 4); },
    2.0, glm::vec3(0.8f, 0.7f, 0.6f),
    vs::EnvironmentMap::SunDisk(64, glm::normalize(glm::vec3(1, 1, 2)), 5.0, glm::vec3(50.0f), glm::vec3(0.2f)));
}

// Two shares agree to one step of 1/65535 (the device's division may round
// differently), and a share is 0 on both sides or on neither.
bool SharesAgree(uint32_t a, uint32_t b)
{
  for (int k = 0; k < 2; ++k)
  {
    const int x = int((a >> (16 * k)) & 65535u), y = int((b >> (16 * k)) & 65535u);
    if (std::abs(x - y) > 1 || (x == 0) != (y == 0))
      return false;
  }
  return true;
}
} // namespace

// Also over a grid filling in, whose unswept directions read swept ones (RedirectDirections): the
// CPU's packing reads Download(), which honours the redirections, so the device's builder must too.
TEST(DirectionTable, DeviceTableIsTheSharedHeadersPacking)
{
  RenderScene scene = MakeScene();
  for (uint32_t resolution : { 8u, 4u, 16u, 2u, 8u })
  for (bool redirected : { false, true })
  {
    if (resolution != scene.Grid->Side() || !redirected)
    {
      vs::VisibilityGridParameters params;
      params.DirectionResolution = resolution;
      scene.Grid->Compute(*scene.Volume, *scene.TF, *scene.Majorants, scene.Geometry, {}, params);
    }
    const uint32_t D = scene.Grid->Side();
    ASSERT_EQ(D, resolution);
    if (redirected)
    {
      const std::vector<float> before = scene.Grid->Download();
      // Every odd direction reads the even one before it, the last the first.
      std::vector<std::pair<uint32_t, uint32_t>> redirects;
      for (uint32_t n = 1; n + 1 < D * D; n += 2)
        redirects.emplace_back(n, n - 1);
      redirects.emplace_back(D * D - 1, 0u);
      scene.Grid->RedirectDirections(redirects);
      ASSERT_NE(scene.Grid->Download(), before) << "the redirections change what the grid reads, D " << D;
    }
    const auto cells = scene.Grid->Cells();
    const uint64_t count = uint64_t(cells[0]) * cells[1] * cells[2];
    const std::vector<float> grid = scene.Grid->Download();
    const std::vector<float> light = scene.Environment->ImportanceLevel(int(vs_log2(D)));
    const float epsilon = 0.01f;
    for (uint32_t strategy : { VS_STRATEGY_VISIBILITY, VS_STRATEGY_TWO_STEP })
    {
      vs::DirectionTable table(scene.Context);
      ASSERT_TRUE(table.Update(*scene.Grid, *scene.Environment, strategy, epsilon));
      const uint32_t nodes = vs_table_nodes(D);
      std::vector<uint32_t> device(count * 2 * nodes);
      table.Nodes().Download(device.data(), device.size() * 4);
      size_t mismatches = 0, zeros = 0;
      for (uint64_t c = 0; c < count; ++c)
      {
        std::vector<float> v((4 * D * D - 1) / 3, 0.0f);
        for (uint32_t n = 0; n < D * D; ++n)
        {
          const float e = grid[c * D * D + n] + epsilon;
          v[n] = strategy == VS_STRATEGY_VISIBILITY ? e : e * light[n];
        }
        for (uint32_t size = D / 2; size > 0; size /= 2)
          for (uint32_t i = 0; i < size * size; ++i)
            v[vs_pyramid_offset(D, size) + i] = vs_pyramid_parent(v.data(), D, 2 * size, uvec2(i % size, i / size));
        for (uint32_t level = 0; (1u << level) < D; ++level)
        {
          const uint32_t n = 1u << level;
          for (uint32_t i = 0; i < n * n; ++i)
          {
            const uvec2 cpu = vs_table_node_from_pyramid(v.data(), D, level, uvec2(i % n, i / n));
            const size_t at = size_t(c) * 2 * nodes + 2 * (vs_env_level_offset(level) + i);
            mismatches += !SharesAgree(cpu.x, device[at]) + !SharesAgree(cpu.y, device[at + 1]);
            zeros += (cpu.x & 65535u) == 0;
          }
        }
      }
      EXPECT_EQ(mismatches, 0u) << (strategy == VS_STRATEGY_VISIBILITY ? "visibility" : "two-step") << ", " << count
                                << " cells, D " << D << (redirected ? ", redirected" : "");
      // Visibility + epsilon is positive everywhere; the sun-disk sky is
      // positive everywhere too.
      EXPECT_EQ(zeros, 0u);
    }
  }
}

// Built once per (grid contents, environment, map, epsilon): the same inputs
// reuse it, a new sweep, a new environment or another epsilon rebuild it;
// Combined and TwoStep share one map.
TEST(DirectionTable, RebuiltExactlyWhenItsInputsChange)
{
  RenderScene scene = MakeScene();
  vs::DirectionTable table(scene.Context);
  ASSERT_TRUE(table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_TWO_STEP, 0.01f));
  EXPECT_EQ(table.Builds(), 1u);
  table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_TWO_STEP, 0.01f);
  table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_COMBINED, 0.01f);
  EXPECT_EQ(table.Builds(), 1u) << "the same inputs (Combined warps TwoStep's map)";
  table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_VISIBILITY, 0.01f);
  EXPECT_EQ(table.Builds(), 2u) << "Visibility's map has no light in it";
  table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_VISIBILITY, 0.02f);
  EXPECT_EQ(table.Builds(), 3u) << "another epsilon";
  const uint64_t before = scene.Grid->ContentSerial();
  scene.Grid->Compute(
    *scene.Volume, *scene.TF, *scene.Majorants, scene.Geometry, {}, vs::VisibilityGridParameters(), { 3u });
  EXPECT_NE(scene.Grid->ContentSerial(), before);
  table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_VISIBILITY, 0.02f);
  EXPECT_EQ(table.Builds(), 4u) << "a sweep changed the grid";
  scene.Environment =
    std::make_unique<vs::DeviceEnvironment>(scene.Context, vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_VISIBILITY, 0.02f);
  EXPECT_EQ(table.Builds(), 5u) << "a new environment";
  EXPECT_THROW(table.Update(*scene.Grid, *scene.Environment, VS_STRATEGY_ENVIRONMENT, 0.02f), vs::InputError);
}

// Rendering from the table is unbiased: Visibility, Combined and TwoStep with
// the table agree with the map built at each scatter event (independent seeds)
// at every pixel, within the standard errors (sum of z^2 over pixels and
// channels, a chi-square with that many degrees of freedom). With the same seed
// they take (almost) the same samples: the 16-bit shares are the map's to 1e-4,
// so the variance per sample is the map's to a few percent (independent seeds
// could not show that: the sun makes the variance estimate itself noisy by
// 10-20%).
TEST(DirectionTable, RenderingFromTheTableIsUnbiased)
{
  RenderScene scene = MakeScene();
  for (uint32_t strategy : { VS_STRATEGY_VISIBILITY, VS_STRATEGY_COMBINED, VS_STRATEGY_TWO_STEP })
  {
    auto p = scene.Params(8, 8, -2.0f, 18.0f, strategy, 512, 3u, true);
    scene.DirectionTable = false;
    auto [a, va] = scene.Render(p, 2);
    EXPECT_FALSE(scene.LastUsedDirectionTable);
    const double n = scene.LastSamples;
    scene.DirectionTable = true;
    auto [same, vsame] = scene.Render(p, 2);
    p.camera.seed = 4u; // independent samples
    auto [b, vb] = scene.Render(p, 2);
    EXPECT_TRUE(scene.LastUsedDirectionTable);
    const vstest::Agreement g = vstest::Compare(a, va, b, vb, n);
    // The same seed: the variance per sample of the map's render and the table's.
    const vstest::Agreement sameSeed = vstest::Compare(a, va, same, vsame, n);
    const double varA = g.varA, varB = g.varB, varSame = sameSeed.varB, chi2 = g.chi2;
    const int dof = g.dof;
    EXPECT_GT(dof, 150);
    EXPECT_LT(chi2, g.Bound()) << "strategy " << strategy;
    EXPECT_NEAR(varSame / varA, 1.0, 0.03) << "strategy " << strategy << ": the same seed, map against table";
    std::printf("[ table ] strategy %u: variance per sample %.4g (map) -> %.4g (table, same seed), %.4g (table, "
                "another seed); chi2 %.1f dof %d\n",
      strategy, varA, varSame, varB, chi2, dof);
  }
}

// The kernel's per-scatter maps read a filling grid's redirected directions too: with every
// direction reading one (a flat grid, whose TwoStep is Environment sampling), the map's render and
// the table's take almost the same samples again, and both differ from TwoStep over the full grid.
TEST(DirectionTable, KernelMapsReadRedirectedDirections)
{
  RenderScene scene = MakeScene();
  auto p = scene.Params(8, 8, -2.0f, 18.0f, VS_STRATEGY_TWO_STEP, 256, 3u, true);
  scene.DirectionTable = false;
  auto [full, vfull] = scene.Render(p, 2);
  const uint32_t D = scene.Grid->Side();
  std::vector<std::pair<uint32_t, uint32_t>> redirects;
  for (uint32_t n = 1; n < D * D; ++n)
    redirects.emplace_back(n, 0u);
  scene.Grid->RedirectDirections(redirects);
  auto [map, vmap] = scene.Render(p, 2);
  EXPECT_FALSE(scene.LastUsedDirectionTable);
  scene.DirectionTable = true;
  auto [table, vtable] = scene.Render(p, 2);
  EXPECT_TRUE(scene.LastUsedDirectionTable);
  const double n = scene.LastSamples;
  const vstest::Agreement sameSeed = vstest::Compare(map, vmap, table, vtable, n);
  const vstest::Agreement grids = vstest::Compare(full, vfull, map, vmap, n);
  EXPECT_NEAR(sameSeed.varB / sameSeed.varA, 1.0, 0.03) << "the same seed over the redirected grid, map against table";
  EXPECT_GT(std::abs(grids.varB / grids.varA - 1.0), 0.1) << "the redirections change TwoStep's pdf";
  EXPECT_LT(grids.chi2, grids.Bound()) << "both are unbiased";
  std::printf("[ redirected ] variance per sample: full grid %.4g, redirected %.4g (map) %.4g (table)\n",
    grids.varA, sameSeed.varA, sameSeed.varB);
}

// By default the render pass rebuilds the table whenever the grid's values change (images do not
// depend on timing: Render.TestMapperManyClipPlanes compares them bit for bit). With a rebuild
// ratio (a grid filling in) it keeps reading a table made from an earlier state of the grid (a
// valid pdf) until it has rendered that many times the build's time with it, but rebuilds at once
// for a new environment (whose light the old table may lack).
TEST(DirectionTable, PassRebuildsForNewGridValuesAtOnceOrOnceTheLastBuildIsPaidFor)
{
  RenderScene scene = MakeScene();
  vs::MonteCarloPass pass(scene.Context);
  auto p = scene.Params(8, 8, -2.0f, 18.0f, VS_STRATEGY_TWO_STEP, 4, 3u, true);
  pass.Reset(8, 8);
  auto render = [&]()
  { pass.Render(*scene.Volume, *scene.TF, *scene.Majorants, scene.Grid.get(), *scene.Environment, p, {}); };
  render();
  EXPECT_TRUE(pass.LastUsedDirectionTable());
  EXPECT_EQ(pass.DirectionTableBuilds(), 1u);
  EXPECT_GT(pass.LastDirectionTableSeconds(), 0.0);
  auto sweep = [&]()
  {
    scene.Grid->Compute(
      *scene.Volume, *scene.TF, *scene.Majorants, scene.Geometry, {}, vs::VisibilityGridParameters(), { 5u });
  };
  sweep();
  render();
  EXPECT_EQ(pass.DirectionTableBuilds(), 2u) << "by default, every change of the grid's values";
  sweep();
  pass.SetTableRebuildRatio(1e9); // never paid for
  render();
  EXPECT_TRUE(pass.LastUsedDirectionTable()) << "the earlier table is still a pdf";
  EXPECT_EQ(pass.DirectionTableBuilds(), 2u);
  EXPECT_EQ(pass.LastDirectionTableSeconds(), 0.0);
  pass.SetTableRebuildRatio(0.0);
  render();
  EXPECT_EQ(pass.DirectionTableBuilds(), 3u) << "paid for at once";
  render();
  EXPECT_EQ(pass.DirectionTableBuilds(), 3u) << "nothing new";
  pass.SetTableRebuildRatio(1e9);
  sweep();
  scene.Environment =
    std::make_unique<vs::DeviceEnvironment>(scene.Context, vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  p.environmentLevels = uint32_t(scene.Environment->FinestLevel());
  render();
  EXPECT_EQ(pass.DirectionTableBuilds(), 4u) << "a new environment is rebuilt whatever the ratio";
}

// TwoStep's defensive mixture with Environment sampling (mc_params.h defensiveWeight) is unbiased in
// the kernel: with the table and with the per-scatter map, its image agrees with plain TwoStep's.
TEST(DirectionTable, DefensiveTwoStepIsUnbiased)
{
  RenderScene scene = MakeScene();
  for (bool table : { true, false })
  {
    scene.DirectionTable = table;
    auto p = scene.Params(8, 8, -2.0f, 18.0f, VS_STRATEGY_TWO_STEP, 512, 3u, true);
    auto [a, va] = scene.Render(p, 2);
    const double n = scene.LastSamples;
    p.defensiveWeight = 0.3f;
    p.camera.seed = 4u; // independent samples
    auto [b, vb] = scene.Render(p, 2);
    EXPECT_EQ(scene.LastUsedDirectionTable, table);
    const vstest::Agreement g = vstest::Compare(a, va, b, vb, n);
    EXPECT_GT(g.dof, 150);
    EXPECT_LT(g.chi2, g.Bound()) << (table ? "table" : "map");
  }
  auto p = scene.Params(8, 8, -2.0f, 18.0f, VS_STRATEGY_TWO_STEP, 4, 3u, true);
  p.defensiveWeight = 1.5f;
  EXPECT_THROW(scene.Render(p, 1), vs::InputError);
}
