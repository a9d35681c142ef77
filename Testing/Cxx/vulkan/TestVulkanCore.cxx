// The Vulkan compute core on the machine's device (lavapipe here): resources,
// dispatch, timings, and the errors that must name their cause and limit.
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vs_spirv_loop_probe.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsPipeline.h"
#include "vsReduceSum.h"

#include "sampling/bindings.h"
#include "sampling/rng.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include <cstdlib>
#include <numeric>

using vs::Context;

TEST(VulkanCore, DefaultDeviceHasComputeAndLimits)
{
  auto ctx = Context::Default();
  const auto& info = ctx->Info();
  EXPECT_FALSE(info.Name.empty());
  EXPECT_GE(info.MaxImageDimension3D, 256u);
  EXPECT_GT(info.MaxStorageBufferRange, 0u);
  EXPECT_GT(info.DeviceLocalHeapBytes, 0u);
  EXPECT_GT(info.SubgroupSize, 0u);
  EXPECT_NE(info.Describe().find("max 3D image dimension"), std::string::npos);
}

TEST(VulkanCore, ReduceSumMatchesCpu)
{
  auto ctx = Context::Default();
  vs::shared::VsRng rng = vs::shared::vs_rng_init(vs::shared::uvec2(1u, 2u), 0u, 9u);
  for (size_t n : { size_t(1), size_t(255), size_t(256), size_t(257), size_t(1000003) })
  {
    std::vector<float> v(n);
    for (auto& x : v)
    {
      x = vs::shared::vs_rng_float(rng);
    }
    double cpu = std::accumulate(v.begin(), v.end(), 0.0);
    double gpu = vs::ReduceSum(ctx).Sum(v);
    EXPECT_NEAR(gpu, cpu, 1e-5 * cpu + 1e-6) << "n = " << n;
  }
}

// A set layout is listed by the names of bindings.h: each type lands at its number, and a set with
// a number left out, given twice or outside the count is refused (a shader and its host code that
// disagree fail at the pipeline's creation, not as a wrong descriptor at run time).
TEST(VulkanCore, BindingTypesPlaceEachTypeAtItsNamedNumber)
{
  using B = vs::BindingType;
  const auto types = vs::BindingTypes(vs::shared::VS_RANGES_BINDING_COUNT,
    { { vs::shared::VS_RANGES_OUTPUT, B::StorageBuffer }, { vs::shared::VS_RANGES_VOLUME, B::StorageImage } });
  ASSERT_EQ(types.size(), 2u);
  EXPECT_EQ(types[0], B::StorageImage);
  EXPECT_EQ(types[1], B::StorageBuffer);
  EXPECT_THROW(vs::BindingTypes(3, { { 0, B::StorageImage }, { 2, B::StorageBuffer } }), std::logic_error);
  EXPECT_THROW(vs::BindingTypes(2, { { 0, B::StorageImage }, { 0, B::StorageBuffer } }), std::logic_error);
  EXPECT_THROW(vs::BindingTypes(2, { { 0, B::StorageImage }, { 2, B::StorageBuffer } }), std::logic_error);
}

TEST(VulkanCore, BufferRoundTrip)
{
  auto ctx = Context::Default();
  std::vector<uint32_t> in(4096), out(4096, 0);
  std::iota(in.begin(), in.end(), 7u);
  vs::Buffer b(ctx, in.size() * 4, "round trip");
  b.Upload(in.data(), in.size() * 4);
  b.Download(out.data(), out.size() * 4);
  EXPECT_EQ(in, out);
  b.Fill(0xdeadbeefu);
  b.Download(out.data(), out.size() * 4);
  EXPECT_EQ(out[0], 0xdeadbeefu);
  EXPECT_EQ(out.back(), 0xdeadbeefu);
}

TEST(VulkanCore, Image3DRoundTripNonPowerOfTwo)
{
  auto ctx = Context::Default();
  const uint32_t w = 13, h = 7, d = 5;
  std::vector<float> in(w * h * d), out(in.size(), -1.0f);
  for (size_t i = 0; i < in.size(); ++i)
  {
    in[i] = float(i) * 0.5f;
  }
  vs::Image3D img(ctx, w, h, d, vk::Format::eR32Sfloat, "round trip");
  img.Upload(in.data(), in.size() * 4);
  img.Download(out.data(), out.size() * 4);
  EXPECT_EQ(in, out);
}

TEST(VulkanCore, OversizedImageThrowsNamingTheLimit)
{
  auto ctx = Context::Default();
  const uint32_t limit = ctx->Info().MaxImageDimension3D;
  try
  {
    vs::Image3D img(ctx, limit + 1, 4, 4, vk::Format::eR32Sfloat, "too wide");
    FAIL() << "no error for an image wider than maxImageDimension3D";
  }
  catch (const vs::DeviceLimitError& e)
  {
    std::string msg = e.what();
    EXPECT_NE(msg.find("maxImageDimension3D"), std::string::npos) << msg;
    EXPECT_NE(msg.find(std::to_string(limit)), std::string::npos) << msg;
    EXPECT_NE(msg.find("too wide"), std::string::npos) << msg;
  }
  // Within the dimension limit but larger than the memory heap.
  EXPECT_THROW(vs::Image3D(ctx, 4096, 4096, 4096, vk::Format::eR32Sfloat, "too big"), vs::DeviceLimitError);
  EXPECT_THROW(vs::Image3D(ctx, 0, 4, 4, vk::Format::eR32Sfloat, "empty"), vs::InputError);
}

TEST(VulkanCore, OversizedBufferThrowsNamingTheLimit)
{
  auto ctx = Context::Default();
  const uint64_t limit = ctx->Info().MaxStorageBufferRange;
  try
  {
    vs::Buffer b(ctx, limit + 1, "too long");
    FAIL() << "no error for a buffer over maxStorageBufferRange";
  }
  catch (const vs::DeviceLimitError& e)
  {
    std::string msg = e.what();
    EXPECT_NE(msg.find("maxStorageBufferRange"), std::string::npos) << msg;
  }
}

TEST(VulkanCore, UnknownDeviceSelectorListsDevices)
{
  vs::ContextOptions opt;
  opt.DeviceSelector = "no-such-device-xyz";
  try
  {
    Context::Create(opt);
    FAIL() << "no error for an unknown device";
  }
  catch (const vs::NoDeviceError& e)
  {
    std::string msg = e.what();
    EXPECT_NE(msg.find("no-such-device-xyz"), std::string::npos) << msg;
    EXPECT_NE(msg.find(Context::Default()->Info().Name), std::string::npos) << msg;
  }
  opt.DeviceSelector = "0";
  EXPECT_NO_THROW(Context::Create(opt));
}

TEST(VulkanCore, NoDriverIsATypedError)
{
  // Point the loader at no driver at all, as on a machine without mesa-vulkan-drivers.
  const char* old = std::getenv("VK_ICD_FILENAMES");
  std::string saved = old ? old : "";
  setenv("VK_ICD_FILENAMES", "/nonexistent/icd.json", 1);
  try
  {
    Context::Create();
    FAIL() << "a context was created without any driver";
  }
  catch (const vs::VulkanUnavailableError& e)
  {
    EXPECT_NE(std::string(e.what()).find("driver"), std::string::npos) << e.what();
  }
  catch (const vs::NoDeviceError& e)
  {
    EXPECT_NE(std::string(e.what()).find("no Vulkan device"), std::string::npos) << e.what();
  }
  if (old)
  {
    setenv("VK_ICD_FILENAMES", saved.c_str(), 1);
  }
  else
  {
    unsetenv("VK_ICD_FILENAMES");
  }
}

TEST(VulkanCore, TimestampsMeasureDispatches)
{
  auto ctx = Context::Default();
  if (!ctx->Info().Timestamps)
  {
    GTEST_SKIP() << "device has no compute timestamps";
  }
  std::vector<float> v(1 << 20, 1.0f);
  EXPECT_NEAR(vs::ReduceSum(ctx).Sum(v), double(v.size()), 1.0);
}

TEST(VulkanCore, ValidationLayersReportNothing)
{
  vs::ContextOptions opt;
  opt.Validation = 1;
  auto ctx = Context::Create(opt);
  if (!ctx->ValidationEnabled())
  {
    GTEST_SKIP() << "VK_LAYER_KHRONOS_validation is not installed";
  }
  {
    std::vector<float> v(100000, 0.25f);
    EXPECT_NEAR(vs::ReduceSum(ctx).Sum(v), 25000.0, 0.1);
    vs::Image3D img(ctx, 9, 8, 7, vk::Format::eR32Sfloat, "validated");
    std::vector<float> data(9 * 8 * 7, 1.0f), back(data.size());
    img.Upload(data.data(), data.size() * 4);
    img.Download(back.data(), back.size() * 4);
    vs::Buffer b(ctx, 1024, "validated buffer");
    b.Fill(0u);
  }
  EXPECT_EQ(ctx->ValidationMessageCount(), 0u);
}

// Issue 35, class 10: the context's pipeline cache has a bound. Every variant a kernel was ever
// compiled for stayed for the process (~100-300 KB of lavapipe code each), so long churn through
// many kinds of setting grew without bound and kept it after the mapper was deleted. Past the
// limit the least recently used pipelines nothing else holds are let go; held ones never are.
namespace
{
std::shared_ptr<vs::ComputePipeline> CachePipeline(int k, const std::string& prefix = "test: cache variant ")
{
  return vs::SharedPipeline(vs::Context::Default(), VS_SPIRV(vs_spirv_loop_probe), { vs::BindingType::StorageBuffer },
    2 * sizeof(uint32_t), prefix + std::to_string(k));
}

bool Holds(const std::string& name)
{
  const auto names = vs::Context::Default()->PipelineNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}
}

TEST(VulkanCore, PipelineCacheIsBounded)
{
  auto ctx = vs::Context::Default();
  auto held = CachePipeline(0); // held here: never let go
  for (int k = 1; k <= 150; ++k)
  {
    CachePipeline(k); // dropped at once: only the cache holds it
  }
  std::printf("%zu pipelines held after 151 variants\n", ctx->PipelineCount());
  EXPECT_LE(ctx->PipelineCount(), 100u) << "the cache keeps every variant";
  EXPECT_TRUE(Holds("test: cache variant 0")) << "a pipeline in use was let go";
  EXPECT_TRUE(Holds("test: cache variant 150")) << "the newest pipeline was let go";
  EXPECT_FALSE(Holds("test: cache variant 1")) << "the least recently used pipeline stayed";
}

TEST(VulkanCore, PipelineCacheRemakesWhatItLetGo)
{
  auto ctx = vs::Context::Default();
  ctx->SetPipelineLimit(2); // nothing else is held here: two stay
  const uint64_t builds = ctx->PipelineBuilds();
  for (int k = 0; k < 5; ++k)
  {
    CachePipeline(k, "test: remake ");
  }
  EXPECT_EQ(ctx->PipelineBuilds(), builds + 5);
  CachePipeline(4, "test: remake "); // still cached: no compile
  EXPECT_EQ(ctx->PipelineBuilds(), builds + 5);
  CachePipeline(0, "test: remake "); // let go: made again, and usable
  EXPECT_EQ(ctx->PipelineBuilds(), builds + 6);
  ctx->SetPipelineLimit(96);
}
