// The pipeline cache on disk (vsPipelineCache.h, issue 39): a file that is not this device's cache as
// VisSweep wrote it is never handed to the driver; the context says so once on stderr, compiles as
// without a cache, and writes a good file; a good file is loaded by the next context.
#include "vsContext.h"
#include "vsPipeline.h"
#include "vsPipelineCache.h"
#include "vsTempDir.h"
#include "vs_spirv_loop_probe.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
vk::PhysicalDeviceProperties FakeDevice()
{
  vk::PhysicalDeviceProperties p;
  p.vendorID = 0x10005;
  p.deviceID = 7;
  p.driverVersion = 0x1234;
  for (uint32_t i = 0; i < VK_UUID_SIZE; ++i)
  {
    p.pipelineCacheUUID[i] = uint8_t(i + 1);
  }
  return p;
}

// The driver's data as a Vulkan pipeline cache starts (VkPipelineCacheHeaderVersionOne), then `payload` bytes.
std::vector<uint8_t> DriverData(const vk::PhysicalDeviceProperties& p, size_t payload)
{
  std::vector<uint8_t> d(32 + payload);
  const uint32_t header[4] = { 32u, uint32_t(VK_PIPELINE_CACHE_HEADER_VERSION_ONE), p.vendorID, p.deviceID };
  std::memcpy(d.data(), header, sizeof(header));
  std::memcpy(d.data() + 16, p.pipelineCacheUUID.data(), VK_UUID_SIZE);
  for (size_t i = 0; i < payload; ++i)
  {
    d[32 + i] = uint8_t(i * 37 + 11);
  }
  return d;
}

std::vector<uint8_t> ReadFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteFile(const std::string& path, const std::vector<uint8_t>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A context whose pipeline cache lives in `dir` (VISSWEEP_PIPELINE_CACHE_DIR while it is made).
std::shared_ptr<vs::Context> ContextIn(const std::string& dir)
{
  setenv("VISSWEEP_PIPELINE_CACHE_DIR", dir.c_str(), 1);
  auto ctx = vs::Context::Create();
  unsetenv("VISSWEEP_PIPELINE_CACHE_DIR");
  return ctx;
}

void Compile(const std::shared_ptr<vs::Context>& ctx)
{
  vs::SharedPipeline(ctx, VS_SPIRV(vs_spirv_loop_probe), { vs::BindingType::StorageBuffer }, 2 * sizeof(uint32_t),
    "test: pipeline cache");
}
}

TEST(PipelineCache, UnwrapGivesBackWhatWrapWrote)
{
  const auto p = FakeDevice();
  const std::vector<uint8_t> data = DriverData(p, 1000);
  std::vector<uint8_t> back;
  EXPECT_EQ(vs::PipelineCache::Unwrap(vs::PipelineCache::Wrap(data), p, back), "");
  EXPECT_EQ(back, data);
}

// Every way a file can be wrong is refused with a reason, and no data reaches the driver.
TEST(PipelineCache, UnwrapRefusesWhatIsNotThisDevicesCache)
{
  const auto p = FakeDevice();
  const std::vector<uint8_t> good = vs::PipelineCache::Wrap(DriverData(p, 1000));
  std::vector<std::pair<std::string, std::vector<uint8_t>>> bad;
  bad.push_back({ "empty", {} });
  bad.push_back({ "a few bytes", { 'V', 'S', 'P' } });
  bad.push_back({ "truncated", std::vector<uint8_t>(good.begin(), good.end() - 1) });
  bad.push_back({ "half", std::vector<uint8_t>(good.begin(), good.begin() + good.size() / 2) });
  auto padded = good;
  padded.push_back(0);
  bad.push_back({ "padded", padded });
  auto flipped = good;
  flipped[good.size() - 100] ^= 0x10;
  bad.push_back({ "a flipped bit in the data", flipped });
  auto magic = good;
  magic[0] = 'X';
  bad.push_back({ "another magic", magic });
  auto version = good;
  version[4] = 99;
  bad.push_back({ "another format version", version });
  bad.push_back({ "the driver's data without VisSweep's header", DriverData(p, 1000) });
  bad.push_back({ "text", std::vector<uint8_t>(1000, 'x') });
  auto other = p;
  other.pipelineCacheUUID[3] ^= 1;
  bad.push_back({ "another driver's UUID", vs::PipelineCache::Wrap(DriverData(other, 1000)) });
  other = p;
  other.deviceID = 8;
  bad.push_back({ "another device", vs::PipelineCache::Wrap(DriverData(other, 1000)) });
  auto noHeader = DriverData(p, 1000);
  noHeader[4] = 2; // header version
  bad.push_back({ "no Vulkan header", vs::PipelineCache::Wrap(noHeader) });
  bad.push_back({ "shorter than a Vulkan header", vs::PipelineCache::Wrap(std::vector<uint8_t>(20, 0)) });
  for (const auto& [what, bytes] : bad)
  {
    std::vector<uint8_t> data = { 1, 2, 3 };
    EXPECT_NE(vs::PipelineCache::Unwrap(bytes, p, data), "") << what;
    EXPECT_TRUE(data.empty()) << what;
  }
}

TEST(PipelineCache, FileNameNamesDeviceAndDriver)
{
  auto p = FakeDevice();
  const std::string a = vs::PipelineCache::FileName(p);
  EXPECT_EQ(a, "pipelines-10005-0007-00001234-0102030405060708090a0b0c0d0e0f10.bin");
  p.driverVersion += 1;
  EXPECT_NE(vs::PipelineCache::FileName(p), a);
}

// A second context loads the file the first wrote after its compile.
TEST(PipelineCache, NextContextLoadsTheFile)
{
  vstest::TempDir dir;
  std::string path;
  {
    auto first = ContextIn(dir.Path.string());
    ASSERT_NE(first->GetPipelineCache(), nullptr);
    path = first->GetPipelineCache()->Path();
    EXPECT_EQ(std::filesystem::path(path).parent_path(), dir.Path);
    EXPECT_FALSE(first->GetPipelineCache()->Loaded()); // no file yet
    Compile(first);
    EXPECT_TRUE(std::filesystem::is_regular_file(path));
  }
  testing::internal::CaptureStderr();
  auto second = ContextIn(dir.Path.string());
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_TRUE(second->GetPipelineCache()->Loaded()) << second->GetPipelineCache()->LastProblem();
  EXPECT_EQ(second->GetPipelineCache()->LastProblem(), "");
  EXPECT_EQ(said.find("pipeline cache"), std::string::npos) << said;
  Compile(second);
}

// Garbage, a truncated file and another device's cache in the file's place: each is ignored with one
// line on stderr naming the file, the pipelines compile as without a cache, and a good file replaces it.
TEST(PipelineCache, BadFilesAreIgnoredWithAMessageAndRewritten)
{
  vstest::TempDir dir;
  std::string path;
  std::vector<uint8_t> good;
  {
    auto ctx = ContextIn(dir.Path.string());
    path = ctx->GetPipelineCache()->Path();
    Compile(ctx);
    good = ReadFile(path);
  }
  ASSERT_GE(good.size(), 24u + 32u); // VisSweep's header and at least the driver's (lavapipe 22.3 keeps only that)
  vk::PhysicalDeviceProperties props = ContextIn("off")->Physical().getProperties();
  auto otherDevice = props;
  otherDevice.pipelineCacheUUID[0] ^= 0xff;
  std::vector<std::pair<std::string, std::vector<uint8_t>>> bad;
  std::vector<uint8_t> garbage(4096);
  for (size_t i = 0; i < garbage.size(); ++i)
  {
    garbage[i] = uint8_t((i * 2654435761u) >> 13);
  }
  bad.push_back({ "garbage", garbage });
  bad.push_back({ "truncated", std::vector<uint8_t>(good.begin(), good.begin() + good.size() / 2) });
  bad.push_back({ "empty", {} });
  auto flipped = good;
  flipped.back() ^= 0x40;
  bad.push_back({ "a flipped bit", flipped });
  bad.push_back({ "another device's", vs::PipelineCache::Wrap(DriverData(otherDevice, 64)) });
  for (const auto& [what, bytes] : bad)
  {
    WriteFile(path, bytes);
    testing::internal::CaptureStderr();
    auto ctx = ContextIn(dir.Path.string());
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(ctx->GetPipelineCache()->Loaded()) << what;
    EXPECT_NE(ctx->GetPipelineCache()->LastProblem(), "") << what;
    EXPECT_NE(said.find("ignoring the pipeline cache " + path), std::string::npos) << what << ": " << said;
    EXPECT_NO_THROW(Compile(ctx)) << what;
    std::vector<uint8_t> data;
    EXPECT_EQ(vs::PipelineCache::Unwrap(ReadFile(path), props, data), "") << what << ": not rewritten";
  }
}

// VISSWEEP_PIPELINE_CACHE_DIR=off: no file is read or written.
TEST(PipelineCache, OffLeavesTheDiskAlone)
{
  auto ctx = ContextIn("off");
  ASSERT_NE(ctx->GetPipelineCache(), nullptr);
  EXPECT_EQ(ctx->GetPipelineCache()->Path(), "");
  Compile(ctx);
  EXPECT_TRUE(ctx->GetPipelineCache()->Save());
}
