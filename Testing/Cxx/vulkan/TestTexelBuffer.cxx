// TestTexelBuffer.cxx — buffers read as uniform texel buffers (Buffer::TexelView,
// DescriptorSet::BindTexels): the render kernel reads its transfer function, environment and
// direction table that way, because lavapipe gathers texel buffers in one vector load where it
// loads a storage buffer lane by lane.
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsPipeline.h"

#include "vs_spirv_texel_probe.h"

#include <gtest/gtest.h>
#include <cstring>
#include <vector>

namespace
{
std::shared_ptr<vs::ComputePipeline> Probe()
{
  using B = vs::BindingType;
  return vs::SharedPipeline(vs::Context::Default(), VS_SPIRV(vs_spirv_texel_probe),
    { B::UniformTexelBuffer, B::UniformTexelBuffer, B::StorageBuffer, B::StorageBuffer, B::StorageBuffer }, 0,
    "test: texel probe");
}
}

TEST(TexelBuffer, ReadsEveryLanesOwnTexel)
{
  auto ctx = vs::Context::Default();
  const uint32_t texels = 37;
  std::vector<float> values(4 * texels);
  for (size_t i = 0; i < values.size(); ++i)
  {
    values[i] = 0.25f * float(i) - 3.0f;
  }
  vs::Buffer data(ctx, values.size() * sizeof(float), "test: texels");
  data.Upload(values.data(), values.size() * sizeof(float));
  // Divergent, repeated and out-of-order indices across the 8 lanes of two groups.
  const std::vector<uint32_t> index{ 36, 0, 5, 5, 17, 2, 33, 1, 9, 9, 9, 20, 0, 36, 11, 28 };
  vs::Buffer idx(ctx, index.size() * sizeof(uint32_t), "test: indices");
  idx.Upload(index.data(), index.size() * sizeof(uint32_t));
  vs::Buffer out(ctx, index.size() * 4 * sizeof(float), "test: fetched vec4");
  vs::Buffer outU(ctx, index.size() * sizeof(uint32_t), "test: fetched uint");
  auto pipeline = Probe();
  vs::DescriptorSet set(*pipeline);
  set.BindTexels(0, data, vk::Format::eR32G32B32A32Sfloat)
    .BindTexels(1, data, vk::Format::eR32Uint)
    .Bind(2, idx)
    .Bind(3, out)
    .Bind(4, outU);
  vs::Batch batch(ctx);
  batch.Dispatch(*pipeline, set, nullptr, 0, uint32_t(index.size() / 8), 1, 1);
  batch.Submit();
  std::vector<float> got(index.size() * 4);
  std::vector<uint32_t> gotU(index.size());
  out.Download(got.data(), got.size() * sizeof(float));
  outU.Download(gotU.data(), gotU.size() * sizeof(uint32_t));
  for (size_t i = 0; i < index.size(); ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_EQ(got[4 * i + c], values[4 * index[i] + c]) << "lane " << i << " channel " << c;
    }
    uint32_t bits;
    std::memcpy(&bits, &values[index[i]], sizeof(bits)); // the r32ui view sees the same bytes
    EXPECT_EQ(gotU[i], bits) << "lane " << i;
  }
}

TEST(TexelBuffer, WrongBindingOrFormatIsAnErrorThatNamesIt)
{
  auto ctx = vs::Context::Default();
  vs::Buffer data(ctx, 64, "test: small table");
  auto pipeline = Probe();
  vs::DescriptorSet set(*pipeline);
  try
  {
    set.BindTexels(2, data, vk::Format::eR32Sfloat); // binding 2 is a storage buffer
    FAIL() << "binding a texel view to a storage-buffer binding must throw";
  }
  catch (const vs::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("no texel buffer at binding 2"), std::string::npos) << e.what();
  }
  try
  {
    set.Bind(0, data); // binding 0 is a texel buffer
    FAIL() << "binding a storage buffer to a texel-buffer binding must throw";
  }
  catch (const vs::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("no storage buffer at binding 0"), std::string::npos) << e.what();
  }
  try
  {
    data.TexelView(vk::Format::eR8Unorm);
    FAIL() << "an unsupported texel format must throw";
  }
  catch (const vs::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("test: small table"), std::string::npos) << e.what();
  }
}
