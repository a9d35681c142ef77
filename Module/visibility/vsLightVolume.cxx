#include "vsLightVolume.h"
#include "sampling/bindings.h"
#include "sampling/light_volume_params.h"
#include "sampling/octahedral.h"
#include "sampling/update_order.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsPipeline.h"
#include "vsVisibilityGrid.h"

#include "vs_spirv_light_volume_r16.h"
#include "vs_spirv_light_volume_r32f.h"
#include "vs_spirv_light_volume_r8.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace vs
{
namespace
{
std::shared_ptr<ComputePipeline> Pipeline(const std::shared_ptr<Context>& context, vk::Format format, uint32_t D)
{
  using B = BindingType;
  const std::vector<B> bindings = BindingTypes(shared::VS_LIGHT_BINDING_COUNT,
    { { shared::VS_LIGHT_VISIBILITY, B::StorageImage }, { shared::VS_LIGHT_SOURCES, B::StorageBuffer },
      { shared::VS_LIGHT_RADIANCE, B::StorageBuffer }, { shared::VS_LIGHT_OUTPUT, B::StorageImage } });
  const uint32_t push = sizeof(shared::VsLightVolumeParams);
  const std::vector<uint32_t> specialization{ D };
  const std::string name = "light volume (D " + std::to_string(D);
  if (format == vk::Format::eR8Unorm)
    return SharedPipeline(context, VS_SPIRV(vs_spirv_light_volume_r8), bindings, push, name + ", r8)", specialization);
  if (format == vk::Format::eR16Unorm)
    return SharedPipeline(
      context, VS_SPIRV(vs_spirv_light_volume_r16), bindings, push, name + ", r16)", specialization);
  return SharedPipeline(context, VS_SPIRV(vs_spirv_light_volume_r32f), bindings, push, name + ", r32f)", specialization);
}
}

LightVolume::LightVolume(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

LightVolume::~LightVolume() = default;

std::vector<glm::vec3> LightVolume::DirectionRadiance(
  const DeviceEnvironment& environment, uint32_t side, double intensity)
{
  if (!(intensity >= 0.0) || !(intensity <= double(std::numeric_limits<float>::max())))
  {
    throw InputError("the light volume's environment intensity must be >= 0 and a finite float, got " +
      std::to_string(intensity));
  }
  if (side < 2 || side > 16 || (side & (side - 1)) != 0)
  {
    throw InputError("the light volume takes 2 to 16 grid directions per side (a power of two), got " +
      std::to_string(side));
  }
  const int level = int(shared::vs_log2_pow2(side));
  if (environment.FinestLevel() < level)
  {
    throw InputError("the environment (" + std::to_string(environment.Size()) + " x " +
      std::to_string(environment.Size()) + " texels) is coarser than the grid's " + std::to_string(side) + " x " +
      std::to_string(side) + " directions: upload it with at least that many");
  }
  // The mean radiance over each grid texel is exact (nested equal-area texels); times its solid angle.
  std::vector<glm::vec3> e = environment.RadianceLevel(level);
  const float scale = float(intensity) * shared::vs_octa_texel_solid_angle(side);
  for (glm::vec3& v : e)
  {
    v *= scale;
  }
  return e;
}

bool LightVolume::Update(const VisibilityGrid& grid, const DeviceEnvironment& environment, double intensity)
{
  if (!grid.Valid())
  {
    throw InputError("the light volume needs a visibility grid: none was computed yet");
  }
  Signature s;
  s.Grid = grid.ContentSerial();
  s.Environment = environment.Serial();
  s.Intensity = intensity;
  if (this->Image_ && s == this->Built_)
  {
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  const uint32_t side = grid.Side();
  const std::vector<glm::vec3> radiance = DirectionRadiance(environment, side, intensity);
  std::vector<glm::vec4> packed(radiance.size());
  for (size_t n = 0; n < radiance.size(); ++n)
  {
    packed[n] = glm::vec4(radiance[n], 0.0f);
  }
  const uint64_t bytes = packed.size() * sizeof(glm::vec4);
  if (!this->Radiance_ || this->Radiance_->Size() != bytes)
  {
    this->Radiance_.reset();
    this->Radiance_ = std::make_unique<Buffer>(this->Context_, bytes, "light volume radiance per direction");
  }
  this->Radiance_->Upload(packed.data(), bytes);

  const std::array<uint32_t, 3> cells = grid.Cells();
  if (!this->Image_ || cells != this->Cells_)
  {
    this->Image_.reset();
    this->Built_ = Signature();
    this->Image_ = std::make_unique<Image3D>(
      this->Context_, cells[0], cells[1], cells[2], vk::Format::eR32G32B32A32Sfloat, "light volume");
    this->Cells_ = cells;
  }
  std::shared_ptr<ComputePipeline> pipeline = Pipeline(this->Context_, grid.Image().Format(), side);
  DescriptorSet set(*pipeline);
  set.Bind(shared::VS_LIGHT_VISIBILITY, grid.Image())
    .Bind(shared::VS_LIGHT_SOURCES, grid.DirectionSourceBuffer())
    .Bind(shared::VS_LIGHT_RADIANCE, *this->Radiance_)
    .Bind(shared::VS_LIGHT_OUTPUT, *this->Image_);
  shared::VsLightVolumeParams params;
  params.cellsX = cells[0];
  params.cellsY = cells[1];
  params.cellsZ = cells[2];
  Batch batch(this->Context_);
  batch.BeginTimer("light volume");
  batch.Dispatch(*pipeline, set, &params, sizeof(params), (cells[0] + 3) / 4, (cells[1] + 3) / 4, (cells[2] + 3) / 4);
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ = batch.Seconds("light volume");
  this->LastWallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->Built_ = s;
  ++this->Builds_;
  return true;
}

std::vector<float> LightVolume::Download() const
{
  std::vector<float> out;
  if (!this->Image_)
  {
    return out;
  }
  out.resize(size_t(4) * this->Cells_[0] * this->Cells_[1] * this->Cells_[2]);
  this->Image_->Download(out.data(), out.size() * sizeof(float));
  return out;
}
}
