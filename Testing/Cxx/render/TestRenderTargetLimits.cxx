// Memory before limits (issue 13, item 7): a render size is checked against the device's limits
// and the host's memory before anything is allocated. A 16384 x 16384 render used to grow past
// 10 GB of host memory before the device's limit error came; now it fails at once, naming the
// limit, and the live heap does not grow.
#include "vsContext.h"
#include "vsError.h"
#include "vsMonteCarloPass.h"
#include "vsRenderTargetLimits.h"

#include <gtest/gtest.h>

#include <malloc.h>

#include <chrono>

namespace
{
long LiveHeapKilobytes()
{
  const struct mallinfo2 m = mallinfo2();
  return long((m.uordblks + m.hblkhd) / 1024);
}
}

TEST(RenderTargetLimits, SmallImagesFit)
{
  auto ctx = vs::Context::Default();
  EXPECT_EQ(vs::RenderTargetLimits::Problem(*ctx, 512, 512), "");
  EXPECT_EQ(vs::RenderTargetLimits::Problem(*ctx, 1, 16384), "");
  EXPECT_NE(vs::RenderTargetLimits::Problem(*ctx, 0, 16), "");
}

TEST(RenderTargetLimits, HugeImageNamesTheLimit)
{
  auto ctx = vs::Context::Default();
  const std::string p = vs::RenderTargetLimits::Problem(*ctx, 16384, 16384);
  EXPECT_NE(p.find("a 16384 x 16384 render (268435456 pixels)"), std::string::npos) << p;
  // lavapipe's maxStorageBufferRange is below the 4 GiB accumulator; on a device with a larger
  // range the heap or the host's memory is the limit that is named.
  const bool named = p.find("maxStorageBufferRange") != std::string::npos ||
    p.find("device-local heap") != std::string::npos || p.find("of host memory") != std::string::npos;
  EXPECT_TRUE(named) << p;
  // Beyond the work-group grid of any device (65535 x 8 pixels is the guaranteed minimum).
  const std::string q = vs::RenderTargetLimits::Problem(*ctx, 1u << 31, 1);
  EXPECT_FALSE(q.empty());
}

TEST(RenderTargetLimits, PassRefusesBeforeAllocating)
{
  auto ctx = vs::Context::Default();
  vs::MonteCarloPass pass(ctx);
  const long before = LiveHeapKilobytes();
  const auto start = std::chrono::steady_clock::now();
  try
  {
    pass.Reset(16384, 16384);
    FAIL() << "a 16384 x 16384 accumulator was allocated";
  }
  catch (const vs::DeviceLimitError& e)
  {
    EXPECT_NE(std::string(e.what()).find("16384 x 16384"), std::string::npos) << e.what();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_LT(LiveHeapKilobytes() - before, 1024) << "the live heap grew";
  // The pass is still usable at a size that fits.
  EXPECT_NO_THROW(pass.Reset(16, 16));
}
