// TestDriverLoopLimit.cxx — the loop budget the render kernel relies on (mc_render.glsl).
// Lavapipe (llvmpipe) ends every loop of a shader invocation once all its loops together have
// taken 65535 back-edges (its loop limiter: one counter per SIMD group, for every loop), without
// an error: the render kernel's sample loop gave wrong pixels past ~130 TwoStep samples per dispatch
// for that reason. The kernel keeps an upper bound of its back-edges below VS_LOOP_BUDGET; this test
// pins that such a budget runs to the end on the device and reports where the device stops.
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsPipeline.h"
#include "sampling/mc_params.h"

#include "vs_spirv_loop_probe.h"

#include <gtest/gtest.h>
#include <cstdio>
#include <vector>

namespace
{
// Inner iterations each of 8 invocations completed, for outer x inner iterations.
std::vector<uint32_t> RunLoops(uint32_t outer, uint32_t inner)
{
  auto ctx = vs::Context::Default();
  auto pipeline = vs::SharedPipeline(ctx, VS_SPIRV(vs_spirv_loop_probe), { vs::BindingType::StorageBuffer },
    2 * sizeof(uint32_t), "test: loop probe");
  vs::Buffer out(ctx, 8 * sizeof(uint32_t), "test: loop probe counts");
  vs::DescriptorSet set(*pipeline);
  set.Bind(0, out);
  const uint32_t push[2] = { outer, inner };
  vs::Batch batch(ctx);
  batch.Dispatch(*pipeline, set, push, sizeof(push), 1, 1, 1);
  batch.Submit();
  std::vector<uint32_t> done(8);
  out.Download(done.data(), done.size() * sizeof(uint32_t));
  return done;
}
}

TEST(DriverLoopLimit, TheKernelsLoopBudgetRunsToTheEnd)
{
  // Back-edges of outer x inner nested loops: outer * (inner + 1); keep them within the budget.
  const uint32_t inner = 99, outer = vs::shared::VS_LOOP_BUDGET / (inner + 1);
  for (uint32_t v : RunLoops(outer, inner))
  {
    EXPECT_EQ(v, outer * inner);
  }
}

TEST(DriverLoopLimit, ReportsWhereTheDeviceEndsLoops)
{
  // Not an assertion about the device (a GPU has no limit): what lavapipe does, for the record.
  const uint32_t inner = 99, outer = 2000; // 200,000 back-edges
  const uint32_t done = RunLoops(outer, inner)[0];
  std::printf("[ loop probe ] %u of %u inner iterations ran (%s)\n", done, outer * inner,
    done == outer * inner ? "no limit" : "the device ended the loops early");
  EXPECT_GE(done, vs::shared::VS_LOOP_BUDGET / (inner + 1) * inner);
}
