// The five strategies as the device runs them: strategies.h compiled to SPIR-V
// (shaders/strategy_samples.comp) and run on the Vulkan device, held against the
// same header compiled as C++ (sample for sample) and against the pdf (chi-square,
// vsChiSquare.h) on a visibility map with an empty region and an environment with
// a sun, a sky and a black ground.
#include "vsChiSquare.h"

#include "sampling/rng.h"
#include "sampling/strategies.h"

#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsPipeline.h"

#include "vs_spirv_strategy_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vs::shared;

namespace
{
constexpr uint kD = 8, kK = 5;

struct DeviceScene
{
  std::vector<float> mips, visibility, product;
};

DeviceScene MakeDeviceScene()
{
  const uint N = 1u << kK;
  std::vector<float> leaves(N * N);
  for (uint y = 0; y < N; ++y)
  {
    for (uint x = 0; x < N; ++x)
    {
      vec3 d = vs_octa_to_dir((vec2(x, y) + 0.5f) / float(N));
      float sky = d.z > 0.0f ? 0.2f + 0.8f * d.z : 0.0f; // black ground
      float sun = glm::dot(d, glm::normalize(vec3(0.6f, -0.3f, 0.74f))) > 0.985f ? 2000.0f : 0.0f;
      leaves[y * N + x] = sky + sun;
    }
  }
  DeviceScene s;
  s.mips = vstest::BuildEnvMips(leaves, kK);
  VsRng rng = vs_rng_init(uvec2(3u, 9u), 1u, 4u);
  s.visibility.resize(kD * kD);
  s.product.resize(kD * kD);
  for (uint i = 0; i < kD * kD; ++i)
  {
    uvec2 t(i % kD, i / kD);
    float v = (t.x < 3 && t.y < 4) ? 0.0f : vs_rng_float(rng); // an occluded block
    s.visibility[i] = v + 0.01f;                                 // + epsilon, as the renderer does
    s.product[i] = vs_product_weight(s.mips.data(), s.visibility[i], t, kD);
  }
  return s;
}

// Device samples for the uniform samples `u`: (direction, pdf) each.
std::vector<glm::vec4> SampleOnDevice(uint strategy, const std::vector<float>& map, const std::vector<float>& mips,
  const std::vector<vec2>& u)
{
  auto ctx = vs::Context::Default();
  using B = vs::BindingType;
  auto pipeline = vs::SharedPipeline(ctx, VS_SPIRV(vs_spirv_strategy_samples),
    { B::StorageBuffer, B::StorageBuffer, B::StorageBuffer, B::StorageBuffer }, sizeof(glm::uvec4),
    "test: strategy samples");
  vs::Buffer uBuf(ctx, u.size() * sizeof(vec2), "test u"), mapBuf(ctx, map.size() * 4, "test map"),
    mipBuf(ctx, mips.size() * 4, "test mips"), out(ctx, u.size() * sizeof(glm::vec4), "test samples");
  uBuf.Upload(u.data(), u.size() * sizeof(vec2));
  mapBuf.Upload(map.data(), map.size() * 4);
  mipBuf.Upload(mips.data(), mips.size() * 4);
  vs::DescriptorSet set(*pipeline);
  set.Bind(0, uBuf).Bind(1, mapBuf).Bind(2, mipBuf).Bind(3, out);
  glm::uvec4 push(strategy, kD, kK, uint(u.size()));
  vs::Batch batch(ctx);
  batch.Dispatch(*pipeline, set, &push, sizeof(push), (uint(u.size()) + 63) / 64, 1, 1);
  batch.Submit();
  std::vector<glm::vec4> result(u.size());
  out.Download(result.data(), result.size() * sizeof(glm::vec4));
  return result;
}

const char* Name(uint s)
{
  static const char* names[] = { "uniform", "environment", "visibility", "combined", "two-step" };
  return names[s];
}
}

// Sample for sample, the device computes what the C++ build of the header computes (up to
// float contraction; a direction may differ only where rounding moves a warp decision).
TEST(SamplingDevice, DeviceSamplesMatchTheCppBuild)
{
  DeviceScene s = MakeDeviceScene();
  const int n = 20000;
  std::vector<vec2> u(n);
  VsRng rng = vs_rng_init(uvec2(5u, 6u), 7u, 8u);
  for (auto& x : u)
  {
    x = vs_rng_vec2(rng);
  }
  for (uint strategy = 0; strategy < 5; ++strategy)
  {
    const std::vector<float>& map = strategy == VS_STRATEGY_VISIBILITY ? s.visibility : s.product;
    std::vector<glm::vec4> device = SampleOnDevice(strategy, map, s.mips, u);
    int differ = 0;
    double worstPdf = 0.0;
    for (int i = 0; i < n; ++i)
    {
      float pdf;
      vec3 d = vs_sample_direction(s.mips.data(), strategy, map.data(), kD, kK, u[i], pdf);
      if (glm::length(d - vec3(device[i])) > 1e-4f)
      {
        ++differ;
        continue;
      }
      worstPdf = std::max(worstPdf, std::abs(double(device[i].w) - pdf) / std::max(double(pdf), 1e-30));
    }
    EXPECT_LE(differ, n / 2000) << Name(strategy) << ": directions differing from the C++ build";
    EXPECT_LT(worstPdf, 1e-4) << Name(strategy) << ": largest relative pdf difference";
  }
}

// The device's samples follow the pdf (computed on the CPU from the same header).
TEST(SamplingDevice, DeviceSamplesMatchPdf)
{
  DeviceScene s = MakeDeviceScene();
  for (uint strategy = 0; strategy < 5; ++strategy)
  {
    const std::vector<float>& map = strategy == VS_STRATEGY_VISIBILITY ? s.visibility : s.product;
    vstest::SamplerTestOptions o;
    o.bins = 64;
    o.sub = 2;
    o.samples = 60000;
    o.seed = 40u + strategy;
    o.edgeResolution = int(std::max(kD, 1u << kK));
    // The u sequence RunSamplerTest draws (vsChiSquare.h), sent to the device up front.
    std::vector<vec2> u(o.samples);
    VsRng rng = vs_rng_init(uvec2(17u, 29u), 3u, o.seed);
    for (auto& x : u)
    {
      x = vs_rng_vec2(rng);
    }
    std::vector<glm::vec4> device = SampleOnDevice(strategy, map, s.mips, u);
    size_t next = 0;
    bool inStep = true;
    auto sample = [&](vec2 ui, float& pdf) {
      inStep = inStep && next < u.size() && ui == u[next];
      const glm::vec4& r = device[std::min(next++, device.size() - 1)];
      pdf = r.w;
      return vec3(r);
    };
    auto pdf = [&](vec3 d) { return vs_pdf_direction(s.mips.data(), strategy, map.data(), kD, kK, d); };
    EXPECT_TRUE(vstest::SamplerMatchesPdf(sample, pdf, o)) << Name(strategy);
    EXPECT_TRUE(inStep && next == u.size()) << "the test's u sequence and the device's went out of step";
  }
}
