// vsDenoisePass.cxx — see vsDenoisePass.h.
#include "vsDenoisePass.h"
#include "sampling/bindings.h"
#include "sampling/denoise_params.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsPipeline.h"

#include "vs_spirv_denoise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vs
{
namespace
{
static_assert(sizeof(shared::VsDenoiseParams) == 32, "VsDenoiseParams: 8 named 4-byte fields (std430)");

void Reserve(std::unique_ptr<Buffer>& b, const std::shared_ptr<Context>& ctx, uint64_t bytes, const char* name)
{
  if (!b || b->Size() < bytes)
  {
    b.reset();
    b = std::make_unique<Buffer>(ctx, bytes, name);
  }
}

std::shared_ptr<ComputePipeline> StagePipeline(const std::shared_ptr<Context>& context, uint32_t stage)
{
  static const char* names[] = { "denoise (moments)", "denoise (box)", "denoise (coefficients)", "denoise (output)" };
  return SharedPipeline(context, VS_SPIRV(vs_spirv_denoise),
    BindingTypes(shared::VS_DENOISE_BINDING_COUNT,
      { { shared::VS_DENOISE_INPUT, BindingType::StorageBuffer }, { shared::VS_DENOISE_SRC, BindingType::StorageBuffer },
        { shared::VS_DENOISE_DST, BindingType::StorageBuffer }, { shared::VS_DENOISE_OUTPUT, BindingType::StorageBuffer } }),
    sizeof(shared::VsDenoiseParams), names[stage], { stage });
}
}

DenoisePass::DenoisePass(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

DenoisePass::~DenoisePass() = default;

std::vector<float> DenoisePass::Filter(const std::vector<float>& estimate, const std::vector<float>& guide,
  const std::vector<float>& variance, uint32_t width, uint32_t height, uint32_t radius, double slopeSpread)
{
  const size_t pixels = size_t(width) * height;
  if (estimate.size() != 4 * pixels || guide.size() != 4 * pixels || variance.size() != 4 * pixels)
  {
    throw std::invalid_argument("DenoisePass: the estimate, the guide and the variance must be " +
      std::to_string(width) + " x " + std::to_string(height) + " rgba images");
  }
  if (pixels == 0)
  {
    return {};
  }
  radius = std::clamp(radius, 1u, 64u);
  // The images scaled to a guide of at most 1 (the model is scale-free; float keeps its range for the
  // squares of dim images), scaled back at the end.
  float largest = 0.0f;
  for (size_t i = 0; i < guide.size(); ++i)
  {
    if (i % 4 != 3 && std::isfinite(guide[i]))
    {
      largest = std::max(largest, std::abs(guide[i]));
    }
  }
  for (size_t i = 0; i < estimate.size(); ++i)
  {
    if (i % 4 != 3 && std::isfinite(estimate[i]))
    {
      largest = std::max(largest, std::abs(estimate[i]));
    }
  }
  const float scale = largest > 0.0f && std::isfinite(1.0f / largest) ? 1.0f / largest : 1.0f;
  std::vector<float> input(12 * pixels);
  for (size_t i = 0; i < 4 * pixels; ++i)
  {
    const bool alpha = i % 4 == 3;
    input[i] = alpha ? estimate[i] : estimate[i] * scale;
    input[4 * pixels + i] = alpha ? 0.0f : guide[i] * scale;
    input[8 * pixels + i] = alpha ? 0.0f : variance[i] * scale * scale;
  }
  const uint64_t plane = uint64_t(pixels) * 4 * sizeof(float);
  Reserve(this->Input_, this->Context_, 3 * plane, "denoise input");
  Reserve(this->X_, this->Context_, shared::VS_DENOISE_MOMENT_PLANES * plane, "denoise planes X");
  Reserve(this->Y_, this->Context_, shared::VS_DENOISE_MOMENT_PLANES * plane, "denoise planes Y");
  Reserve(this->Output_, this->Context_, plane, "denoise output");
  this->Input_->Upload(input.data(), 3 * plane);

  std::shared_ptr<ComputePipeline> stages[4];
  for (uint32_t s = 0; s < 4; ++s)
  {
    stages[s] = StagePipeline(this->Context_, s);
  }
  // The planes swap between X and Y: each stage reads one and writes the other.
  auto bind = [&](const ComputePipeline& pipeline, const Buffer& src, const Buffer& dst) {
    auto set = std::make_unique<DescriptorSet>(pipeline);
    set->Bind(shared::VS_DENOISE_INPUT, *this->Input_)
      .Bind(shared::VS_DENOISE_SRC, src)
      .Bind(shared::VS_DENOISE_DST, dst)
      .Bind(shared::VS_DENOISE_OUTPUT, *this->Output_);
    return set;
  };
  auto momentsSet = bind(*stages[0], *this->Y_, *this->X_);
  auto boxXY = bind(*stages[1], *this->X_, *this->Y_);
  auto boxYX = bind(*stages[1], *this->Y_, *this->X_);
  auto coefficientsSet = bind(*stages[2], *this->X_, *this->Y_);
  auto outputSet = bind(*stages[3], *this->Y_, *this->X_);

  shared::VsDenoiseParams p{};
  p.width = width;
  p.height = height;
  p.radius = radius;
  const double n = double(2 * radius + 1) * double(2 * radius + 1);
  const double tau = slopeSpread > 0.0 && std::isfinite(slopeSpread) ? slopeSpread : kSlopeSpread;
  p.priorScale = float(1.0 / (n * tau * tau));
  const uint32_t gx = (width + 7) / 8, gy = (height + 7) / 8;
  Batch batch(this->Context_);
  // The separable box filter of the first `planes` planes: along x through `alongX`, then along y through
  // `alongY` (which reads what the first wrote), each followed by a barrier.
  auto box = [&](uint32_t planes, const DescriptorSet& alongX, const DescriptorSet& alongY) {
    p.planes = planes;
    p.axis = 0;
    batch.Dispatch(*stages[1], alongX, &p, sizeof(p), gx, gy);
    batch.Barrier();
    p.axis = 1;
    batch.Dispatch(*stages[1], alongY, &p, sizeof(p), gx, gy);
    batch.Barrier();
  };
  batch.BeginTimer("denoise");
  batch.Dispatch(*stages[0], *momentsSet, &p, sizeof(p), gx, gy); // moments -> X
  batch.Barrier();
  box(shared::VS_DENOISE_MOMENT_PLANES, *boxXY, *boxYX); // X -> Y -> X: the window means
  batch.Dispatch(*stages[2], *coefficientsSet, &p, sizeof(p), gx, gy); // X -> (a, b) in Y
  batch.Barrier();
  box(shared::VS_DENOISE_COEFFICIENT_PLANES, *boxYX, *boxXY); // Y -> X -> Y: the coefficients' means
  batch.Dispatch(*stages[3], *outputSet, &p, sizeof(p), gx, gy); // a g + b -> output
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ = batch.Seconds("denoise");

  std::vector<float> out(4 * pixels);
  this->Output_->Download(out.data(), plane);
  const float unscale = 1.0f / scale;
  for (size_t i = 0; i < out.size(); ++i)
  {
    if (i % 4 != 3)
    {
      out[i] *= unscale;
    }
  }
  return out;
}
}
