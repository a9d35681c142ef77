#include "vsLightVolume.h"
#include "sampling/bindings.h"
#include "sampling/light_volume_params.h"
#include "sampling/octahedral.h"
#include "sampling/phase_moments.h"
#include "sampling/update_order.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsPipeline.h"
#include "vsVisibilityGrid.h"

#include "vsDeviceVolume.h"
#include "vsSweepPlan.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_light_volume_albedo.h"
#include "vs_spirv_light_volume_lights.h"
#include "vs_spirv_light_volume_r16.h"
#include "vs_spirv_light_volume_scatter_r16.h"
#include "vs_spirv_light_volume_scatter_r32f.h"
#include "vs_spirv_light_volume_scatter_r8.h"
#include "vs_spirv_light_volume_r32f.h"
#include "vs_spirv_light_volume_r8.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace vs
{
namespace
{
std::shared_ptr<ComputePipeline> Pipeline(
  const std::shared_ptr<Context>& context, vk::Format format, uint32_t D, uint32_t moment)
{
  using B = BindingType;
  const std::vector<B> bindings = BindingTypes(shared::VS_LIGHT_BINDING_COUNT,
    { { shared::VS_LIGHT_VISIBILITY, B::StorageImage }, { shared::VS_LIGHT_SOURCES, B::StorageBuffer },
      { shared::VS_LIGHT_RADIANCE, B::StorageBuffer }, { shared::VS_LIGHT_OUTPUT, B::StorageImage },
      { shared::VS_LIGHT_MOMENT, B::StorageImage } });
  const uint32_t push = sizeof(shared::VsLightVolumeParams);
  const std::vector<uint32_t> specialization{ D, moment };
  const std::string name = std::string(moment == 2u ? "light volume with its moment, the first order's apart (D "
      : moment                                  ? "light volume with its moment (D "
                                                : "light volume (D ") +
    std::to_string(D);
  if (format == vk::Format::eR8Unorm)
    return SharedPipeline(context, VS_SPIRV(vs_spirv_light_volume_r8), bindings, push, name + ", r8)", specialization);
  if (format == vk::Format::eR16Unorm)
    return SharedPipeline(
      context, VS_SPIRV(vs_spirv_light_volume_r16), bindings, push, name + ", r16)", specialization);
  return SharedPipeline(context, VS_SPIRV(vs_spirv_light_volume_r32f), bindings, push, name + ", r32f)", specialization);
}

std::vector<BindingType> ScatterBindings()
{
  using B = BindingType;
  return BindingTypes(shared::VS_LIGHTMS_BINDING_COUNT,
    { { shared::VS_LIGHTMS_VOLUME, B::StorageImage }, { shared::VS_LIGHTMS_TF, B::UniformTexelBuffer },
      { shared::VS_LIGHTMS_PARAMS, B::StorageBuffer }, { shared::VS_LIGHTMS_ALBEDO, B::StorageImage },
      { shared::VS_LIGHTMS_LIGHT, B::StorageImage }, { shared::VS_LIGHTMS_EMIT_IN, B::StorageImage },
      { shared::VS_LIGHTMS_EMIT_OUT, B::StorageImage }, { shared::VS_LIGHTMS_VISIBILITY, B::StorageImage },
      { shared::VS_LIGHTMS_SOURCES, B::StorageBuffer }, { shared::VS_LIGHTMS_STEPS, B::StorageBuffer },
      { shared::VS_LIGHTMS_ORDER_IN, B::StorageImage }, { shared::VS_LIGHTMS_ORDER_OUT, B::StorageImage },
      { shared::VS_LIGHTMS_DIRECT, B::StorageImage }, { shared::VS_LIGHTMS_TRANSMITTANCE, B::StorageImage },
      { shared::VS_LIGHTMS_SCENE, B::StorageBuffer }, { shared::VS_LIGHTMS_MOMENT, B::StorageImage },
      { shared::VS_LIGHTMS_MOMENT_SUM, B::StorageImage }, { shared::VS_LIGHTMS_ORDER_MOMENT, B::StorageImage } });
}

// The scatter's variants (light_volume_scatter.glsl's VS_SPEC_SIMILAR).
enum class ScatterMedium : uint32_t
{
  Isotropic = 0,
  Similar = 1,        // the orders k >= 3 under g != 0
  SimilarFromLobe = 2 // the order k = 2 under g != 0: its source is the first order's lobe
};

std::shared_ptr<ComputePipeline> ScatterPipeline(
  const std::shared_ptr<Context>& context, vk::Format format, uint32_t D, ScatterMedium medium)
{
  const uint32_t push = sizeof(shared::VsLightScatterParams);
  const std::vector<uint32_t> specialization{ D, uint32_t(medium) };
  const std::string name = std::string(medium == ScatterMedium::Isotropic ? "light volume scatter (D "
        : medium == ScatterMedium::Similar ? "light volume scatter, similar medium (D "
                                           : "light volume scatter, from the first order's lobe (D ") +
    std::to_string(D);
  if (format == vk::Format::eR8Unorm)
    return SharedPipeline(
      context, VS_SPIRV(vs_spirv_light_volume_scatter_r8), ScatterBindings(), push, name + ", r8)", specialization);
  if (format == vk::Format::eR16Unorm)
    return SharedPipeline(
      context, VS_SPIRV(vs_spirv_light_volume_scatter_r16), ScatterBindings(), push, name + ", r16)", specialization);
  return SharedPipeline(
    context, VS_SPIRV(vs_spirv_light_volume_scatter_r32f), ScatterBindings(), push, name + ", r32f)", specialization);
}

// FNV-1a over bytes: the signature of what the multiple scattering reads besides grid and environment.
uint64_t Hash(uint64_t h, const void* data, size_t bytes)
{
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i)
  {
    h = (h ^ p[i]) * 1099511628211ull;
  }
  return h;
}

// What a pass that marches the medium reads of it: the volume, its transfer function and its parameters.
uint64_t HashMedium(uint64_t h, const LightVolume::MultipleScattering& m)
{
  const uintptr_t volume = reinterpret_cast<uintptr_t>(m.Volume);
  h = Hash(h, &volume, sizeof(volume));
  const TransferFunctionSamples& tf = m.TF->Samples();
  h = Hash(h, &tf.ScalarMin, sizeof(float));
  h = Hash(h, &tf.ScalarMax, sizeof(float));
  h = Hash(h, tf.Entries.data(), tf.Entries.size() * sizeof(float));
  return Hash(h, &m.Params, sizeof(m.Params));
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
  MultipleScattering single;
  single.Orders = 1;
  return this->Update(grid, environment, intensity, single);
}

bool LightVolume::Update(const VisibilityGrid& grid, const DeviceEnvironment& environment, double intensity,
  const MultipleScattering& scattering)
{
  const bool multiple = scattering.Orders >= 2 && scattering.Events >= 2;
  const bool lit = !scattering.Lights.empty();
  if ((multiple || lit) && (!scattering.Volume || !scattering.TF))
  {
    throw InputError(std::string("the light volume's ") + (multiple ? "multiple scattering" : "lights") +
      " need the volume and its transfer function");
  }
  if (scattering.Lights.size() > shared::VS_MAX_SCENE_LIGHTS)
  {
    throw InputError("the light volume takes at most " + std::to_string(shared::VS_MAX_SCENE_LIGHTS) + " lights, got " +
      std::to_string(scattering.Lights.size()));
  }
  if (multiple && !(scattering.MaxRatio >= 0.0f && scattering.MaxRatio < 1.0f))
  {
    throw InputError("the light volume's largest ratio between orders must lie in [0, 1)");
  }
  if (!grid.Valid())
  {
    throw InputError("the light volume needs a visibility grid: none was computed yet");
  }
  Signature s;
  s.Grid = grid.ContentSerial();
  s.Environment = environment.Serial();
  s.Intensity = intensity;
  if (!std::isfinite(scattering.Anisotropy) || std::abs(scattering.Anisotropy) >= 1.0f)
  {
    throw InputError("the light volume's phase anisotropy must lie in (-1, 1), got " +
      std::to_string(scattering.Anisotropy));
  }
  // The orders 2 .. Events in the similar medium of g (vsLightVolume.h): where the phase is not isotropic.
  const bool similar = multiple && std::abs(scattering.Anisotropy) >= shared::VS_HG_ISOTROPIC_G;
  if (multiple)
  {
    const MultipleScattering& m = scattering;
    uint64_t h = HashMedium(14695981039346656037ull, m);
    const uint32_t counts[4] = { std::min(m.Orders, m.Events), m.Events, m.AlbedoSamples, m.DirectionStride };
    h = Hash(h, counts, sizeof(counts));
    h = Hash(h, &m.MaxRatio, sizeof(m.MaxRatio));
    if (similar)
    {
      h = Hash(h, &m.Anisotropy, sizeof(m.Anisotropy)); // the orders >= 2 depend on g's value
    }
    s.Scattering = h | 1u; // never 0
  }
  if (lit)
  {
    // What the lights' march reads: the lights, the volume, its transfer function and parameters, the step.
    const MultipleScattering& m = scattering;
    uint64_t h = HashMedium(1099511628211ull, m);
    h = Hash(h, m.Lights.data(), m.Lights.size() * sizeof(shared::VsSceneLight));
    h = Hash(h, &m.LightStep, sizeof(m.LightStep));
    s.Lights = h | 1u;
  }
  // The first order's band-1 moment depends on whether the phase is anisotropic, not on g's value (vsLightVolume.h).
  s.Moment = scattering.Anisotropy != 0.0f;
  if (this->Image_ && s.ServedBy(this->Built_))
  {
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  const uint32_t side = grid.Side();
  const std::vector<glm::vec3> radiance = DirectionRadiance(environment, side, intensity);
  // E_n, then each direction w_n (read by the moment's build).
  std::vector<glm::vec4> packed(2 * radiance.size());
  for (size_t n = 0; n < radiance.size(); ++n)
  {
    packed[n] = glm::vec4(radiance[n], 0.0f);
    packed[radiance.size() + n] = glm::vec4(SweepPlan::Direction(uint32_t(n), grid.Parameters()), 0.0f);
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
  // With the orders >= 2 under g < 0, the first order's lobe kept apart in layers 3 .. 5 (the preview reads it
  // and the other orders' as two lobes; vsLightVolume.h).
  const uint32_t momentLayers = s.Moment ? (similar && scattering.Anisotropy < 0.0f ? 6u : 3u) : 0u;
  if (s.Moment && (!this->Moment_ || this->Moment_->Width() != cells[0] || this->Moment_->Height() != cells[1] ||
                    this->Moment_->Depth() != momentLayers * cells[2]))
  {
    this->Moment_.reset();
    this->Moment_ = std::make_unique<Image3D>(this->Context_, cells[0], cells[1], momentLayers * cells[2],
      vk::Format::eR32G32B32A32Sfloat, "light volume band-1 moment");
  }
  std::shared_ptr<ComputePipeline> pipeline =
    Pipeline(this->Context_, grid.Image().Format(), side, momentLayers == 6u ? 2u : s.Moment ? 1u : 0u);
  DescriptorSet set(*pipeline);
  set.Bind(shared::VS_LIGHT_VISIBILITY, grid.Image())
    .Bind(shared::VS_LIGHT_SOURCES, grid.DirectionSourceBuffer())
    .Bind(shared::VS_LIGHT_RADIANCE, *this->Radiance_)
    .Bind(shared::VS_LIGHT_OUTPUT, *this->Image_)
    .Bind(shared::VS_LIGHT_MOMENT, s.Moment ? *this->Moment_ : *this->Image_); // unwritten without
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
  this->LastScatterSeconds_ = 0.0;
  this->Built_ = Signature(); // a build that throws half-way is built again
  if (lit)
  {
    this->LightPass(grid, scattering);
  }
  this->BuiltLights_ = scattering.Lights;
  if (multiple)
  {
    this->Scatter(grid, scattering, lit, similar);
  }
  this->LastWallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->Built_ = s;
  ++this->Builds_;
  return true;
}

// VTK's lights: per cell the transmittance towards each light and the direct light (light_volume_lights.comp).
void LightVolume::LightPass(const VisibilityGrid& grid, const MultipleScattering& m)
{
  const std::array<uint32_t, 3> cells = this->Cells_;
  const auto image = [&](std::unique_ptr<Image3D>& img, uint32_t depth, const char* name) {
    if (!img || img->Width() != cells[0] || img->Height() != cells[1] || img->Depth() != depth)
    {
      img.reset();
      img = std::make_unique<Image3D>(this->Context_, cells[0], cells[1], depth, vk::Format::eR32G32B32A32Sfloat, name);
    }
  };
  image(this->Direct_, cells[2], "light volume direct light of the scene lights");
  image(this->Transmittance_, 2 * cells[2], "light volume transmittance towards the scene lights");
  shared::VsLightSceneParams params{};
  params.volume = m.Params;
  params.indexToWorld = glm::inverse(m.Params.worldToIndex);
  params.cellSize = grid.CellSize();
  params.lightCount = uint32_t(m.Lights.size());
  params.cells = glm::uvec3(cells[0], cells[1], cells[2]);
  float step = m.LightStep;
  if (!(step > 0.0f))
  {
    // The smallest voxel spacing: the world length of one index unit along each axis.
    step = std::numeric_limits<float>::max();
    for (int a = 0; a < 3; ++a)
    {
      step = std::min(step, glm::length(glm::vec3(params.indexToWorld[a])));
    }
  }
  params.step = step;
  for (size_t i = 0; i < m.Lights.size(); ++i)
  {
    params.lights[i] = m.Lights[i];
  }
  if (!this->SceneParams_)
  {
    this->SceneParams_ = std::make_unique<Buffer>(this->Context_, sizeof(params), "light volume scene lights");
  }
  this->SceneParams_->Upload(&params, sizeof(params));
  if (!this->AlbedoParams_)
  {
    this->AlbedoParams_ =
      std::make_unique<Buffer>(this->Context_, sizeof(shared::VsLightAlbedoParams), "light volume albedo parameters");
  }
  const std::shared_ptr<ComputePipeline> pipeline = SharedPipeline(this->Context_,
    VS_SPIRV(vs_spirv_light_volume_lights), ScatterBindings(), 0, "light volume scene lights");
  DescriptorSet set(*pipeline);
  // Every binding of the shared layout; the pass reads the volume, the table, its parameters and writes two.
  set.Bind(shared::VS_LIGHTMS_VOLUME, m.Volume->Image())
    .BindTexels(shared::VS_LIGHTMS_TF, m.TF->Lut(), vk::Format::eR32G32B32A32Sfloat)
    .Bind(shared::VS_LIGHTMS_PARAMS, *this->AlbedoParams_)
    .Bind(shared::VS_LIGHTMS_ALBEDO, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_LIGHT, *this->Image_)
    .Bind(shared::VS_LIGHTMS_EMIT_IN, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_EMIT_OUT, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_VISIBILITY, grid.Image())
    .Bind(shared::VS_LIGHTMS_SOURCES, grid.DirectionSourceBuffer())
    .Bind(shared::VS_LIGHTMS_STEPS, *this->SceneParams_)
    .Bind(shared::VS_LIGHTMS_ORDER_IN, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_ORDER_OUT, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_DIRECT, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_TRANSMITTANCE, *this->Transmittance_)
    .Bind(shared::VS_LIGHTMS_SCENE, *this->SceneParams_)
    .Bind(shared::VS_LIGHTMS_MOMENT, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_MOMENT_SUM, *this->Direct_)
    .Bind(shared::VS_LIGHTMS_ORDER_MOMENT, *this->Direct_);
  Batch batch(this->Context_);
  batch.BeginTimer("lights");
  batch.Dispatch(*pipeline, set, nullptr, 0, (cells[0] + 3) / 4, (cells[1] + 3) / 4, (cells[2] + 3) / 4);
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ += batch.Seconds("lights");
}

std::vector<float> LightVolume::DownloadTransmittance() const
{
  std::vector<float> out;
  if (!this->Transmittance())
  {
    return out;
  }
  out.resize(size_t(4) * this->Cells_[0] * this->Cells_[1] * 2 * this->Cells_[2]);
  this->Transmittance_->Download(out.data(), out.size() * sizeof(float));
  return out;
}

void LightVolume::Scatter(const VisibilityGrid& grid, const MultipleScattering& m, bool lit, bool similar)
{
  const std::array<uint32_t, 3> cells = this->Cells_;
  const uint32_t side = grid.Side();
  const auto image = [&](std::unique_ptr<Image3D>& img, const char* name) {
    if (!img || img->Width() != cells[0] || img->Height() != cells[1] || img->Depth() != cells[2])
    {
      img.reset();
      img = std::make_unique<Image3D>(this->Context_, cells[0], cells[1], cells[2], vk::Format::eR32G32B32A32Sfloat, name);
    }
  };
  image(this->Albedo_, "light volume albedo");
  image(this->EmitA_, "light volume emission A");
  image(this->EmitB_, "light volume emission B");
  image(this->OrderA_, "light volume order A");
  image(this->OrderB_, "light volume order B");
  const auto layers = [&](std::unique_ptr<Image3D>& img, const char* name) {
    if (!img || img->Width() != cells[0] || img->Height() != cells[1] || img->Depth() != 3 * cells[2])
    {
      img.reset();
      img = std::make_unique<Image3D>(
        this->Context_, cells[0], cells[1], 3 * cells[2], vk::Format::eR32G32B32A32Sfloat, name);
    }
  };
  if (similar)
  {
    layers(this->MomentSum_, "light volume band-1 moment of the orders 2 ..");
    layers(this->OrderMoment_, "light volume band-1 moment of an order");
  }

  // Each direction's step in cells: the world direction in index space, per cell, one cell along its
  // longest axis; then each direction's world direction w_n (read in the similar medium, for the moment).
  std::vector<glm::vec4> steps(size_t(2) * side * side);
  const glm::mat3 toIndex(m.Params.worldToIndex);
  const glm::vec3 cellSize = grid.CellSize();
  for (uint32_t n = 0; n < side * side; ++n)
  {
    const glm::vec3 d = toIndex * SweepPlan::Direction(n, grid.Parameters()) / cellSize;
    const float longest = std::max(std::abs(d.x), std::max(std::abs(d.y), std::abs(d.z)));
    steps[n] = glm::vec4(longest > 0.0f ? d / longest : glm::vec3(0.0f), 0.0f);
    steps[side * side + n] = glm::vec4(SweepPlan::Direction(n, grid.Parameters()), 0.0f);
  }
  const uint64_t stepBytes = steps.size() * sizeof(glm::vec4);
  if (!this->Steps_ || this->Steps_->Size() != stepBytes)
  {
    this->Steps_.reset();
    this->Steps_ = std::make_unique<Buffer>(this->Context_, stepBytes, "light volume steps per direction");
  }
  this->Steps_->Upload(steps.data(), stepBytes);

  shared::VsLightAlbedoParams albedo{};
  albedo.volume = m.Params;
  albedo.cellSize = cellSize;
  albedo.samplesPerAxis = std::max(1u, std::min(m.AlbedoSamples, 16u));
  albedo.cells = glm::uvec3(cells[0], cells[1], cells[2]);
  albedo.lit = lit ? 1u : 0u;
  if (!this->AlbedoParams_)
  {
    this->AlbedoParams_ = std::make_unique<Buffer>(this->Context_, sizeof(albedo), "light volume albedo parameters");
  }
  this->AlbedoParams_->Upload(&albedo, sizeof(albedo));

  const std::shared_ptr<ComputePipeline> albedoPipeline = SharedPipeline(this->Context_,
    VS_SPIRV(vs_spirv_light_volume_albedo), ScatterBindings(), 0, "light volume albedo");
  const std::shared_ptr<ComputePipeline> scatter = ScatterPipeline(
    this->Context_, grid.Image().Format(), side, similar ? ScatterMedium::Similar : ScatterMedium::Isotropic);
  // The order k = 2 under g != 0 (the first order's light by the real phase) has a variant of its own.
  const std::shared_ptr<ComputePipeline> scatterFromLobe =
    similar ? ScatterPipeline(this->Context_, grid.Image().Format(), side, ScatterMedium::SimilarFromLobe) : scatter;
  const auto bindAll = [&](DescriptorSet& set, const Image3D& in, const Image3D& out, const Image3D& orderIn,
                       const Image3D& orderOut) {
    set.Bind(shared::VS_LIGHTMS_VOLUME, m.Volume->Image())
      .BindTexels(shared::VS_LIGHTMS_TF, m.TF->Lut(), vk::Format::eR32G32B32A32Sfloat)
      .Bind(shared::VS_LIGHTMS_PARAMS, *this->AlbedoParams_)
      .Bind(shared::VS_LIGHTMS_ALBEDO, *this->Albedo_)
      .Bind(shared::VS_LIGHTMS_LIGHT, *this->Image_)
      .Bind(shared::VS_LIGHTMS_EMIT_IN, in)
      .Bind(shared::VS_LIGHTMS_EMIT_OUT, out)
      .Bind(shared::VS_LIGHTMS_VISIBILITY, grid.Image())
      .Bind(shared::VS_LIGHTMS_SOURCES, grid.DirectionSourceBuffer())
      .Bind(shared::VS_LIGHTMS_STEPS, *this->Steps_)
      .Bind(shared::VS_LIGHTMS_ORDER_IN, orderIn)
      .Bind(shared::VS_LIGHTMS_ORDER_OUT, orderOut)
      // The lights' (read by the albedo pass with lit; placeholders otherwise, unread)
      .Bind(shared::VS_LIGHTMS_DIRECT, lit ? *this->Direct_ : *this->Albedo_)
      .Bind(shared::VS_LIGHTMS_TRANSMITTANCE, lit ? *this->Transmittance_ : *this->Albedo_)
      .Bind(shared::VS_LIGHTMS_SCENE, lit ? *this->SceneParams_ : *this->AlbedoParams_)
      // The moment's (similar; placeholders otherwise, unread)
      .Bind(shared::VS_LIGHTMS_MOMENT, similar ? *this->Moment_ : *this->Albedo_)
      .Bind(shared::VS_LIGHTMS_MOMENT_SUM, similar ? *this->MomentSum_ : *this->Albedo_)
      .Bind(shared::VS_LIGHTMS_ORDER_MOMENT, similar ? *this->OrderMoment_ : *this->Albedo_);
  };
  const uint32_t gx = (cells[0] + 3) / 4, gy = (cells[1] + 3) / 4, gz = (cells[2] + 3) / 4;
  const uint32_t orders = std::min(m.Orders, m.Events);
  uint32_t stride = 1;
  while (stride * 2 <= std::min(m.DirectionStride, side / 2))
  {
    stride *= 2; // a power of two that divides D
  }
  Batch batch(this->Context_);
  batch.BeginTimer("scatter");
  // The sets live until the batch is submitted.
  std::vector<std::unique_ptr<DescriptorSet>> sets;
  sets.push_back(std::make_unique<DescriptorSet>(*albedoPipeline));
  bindAll(*sets.back(), *this->EmitB_, *this->EmitA_, *this->OrderB_, *this->OrderA_); // E_1, I_1 into A
  batch.Dispatch(*albedoPipeline, *sets.back(), nullptr, 0, gx, gy, gz);
  Image3D* in = this->EmitA_.get();
  Image3D* out = this->EmitB_.get();
  Image3D* orderIn = this->OrderA_.get();
  Image3D* orderOut = this->OrderB_.get();
  for (uint32_t k = 2; k <= orders; ++k)
  {
    batch.Barrier();
    const ComputePipeline& pipeline = k == 2 ? *scatterFromLobe : *scatter;
    sets.push_back(std::make_unique<DescriptorSet>(pipeline));
    bindAll(*sets.back(), *in, *out, *orderIn, *orderOut);
    shared::VsLightScatterParams params{};
    params.cellsX = cells[0];
    params.cellsY = cells[1];
    params.cellsZ = cells[2];
    params.stride = stride;
    params.offsetX = stride > 1 ? (k - 2) % stride : 0u;
    params.offsetY = stride > 1 ? ((k - 2) / stride) % stride : 0u;
    if (similar)
    {
      // The order k = 2 scatters the first order's light by the real phase (scatterFromLobe), the others
      // carry on in the similar medium (light_volume_scatter.glsl).
      params.anisotropy = m.Anisotropy;
    }
    batch.Dispatch(pipeline, *sets.back(), &params, sizeof(params), gx, gy, gz);
    std::swap(in, out);
    std::swap(orderIn, orderOut);
  }
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ += batch.Seconds("scatter");
  this->LastScatterSeconds_ = batch.Seconds("scatter");
  if (orders >= 2 && (m.Events > orders || similar))
  {
    // After the last swap orderIn holds I_K, orderOut I_{K-1}.
    this->AddTail(*orderIn, *orderOut, m.Events - orders, m.MaxRatio, similar ? this->MomentSum_.get() : nullptr,
      similar ? this->OrderMoment_.get() : nullptr);
  }
}

// The orders K+1 .. K+N as a geometric series, per cell and channel: I_K sum_{m=1..N} r^m with r the
// cell's ratio I_K / I_{K-1}, at most the whole volume's (sum over cells of I_K / of I_{K-1}: the
// operator's dominant eigenvalue, which every cell's ratio approaches) and maxRatio. The global bound
// keeps cells deep in a dense medium, whose light still grows from order to order (it diffuses in
// from the surface), from extrapolating that growth. On the host: a reduction and one pass over the
// cells (109 k on ch2: milliseconds).
void LightVolume::AddTail(const Image3D& last, const Image3D& before, uint32_t events, float maxRatio,
  const Image3D* momentSum, const Image3D* lastMoment)
{
  const size_t n = size_t(this->Cells_[0]) * this->Cells_[1] * this->Cells_[2];
  std::vector<float> total(4 * n), k(4 * n), k1(4 * n), moment, momentK;
  if (momentSum && lastMoment)
  {
    // The light volume's moment: the first order's, the orders 2 .. K's and the tail's, the last order's M_K
    // times the same series per cell and channel as I_K.
    moment.resize(size_t(4) * this->Moment_->Width() * this->Moment_->Height() * this->Moment_->Depth());
    momentK.resize(12 * n);
    std::vector<float> sum(12 * n);
    this->Moment_->Download(moment.data(), moment.size() * sizeof(float));
    momentSum->Download(sum.data(), sum.size() * sizeof(float));
    lastMoment->Download(momentK.data(), momentK.size() * sizeof(float));
    for (size_t i = 0; i < sum.size(); ++i)
    {
      moment[i] += sum[i]; // layers 0 .. 2 (3 .. 5: the first order's, apart)
    }
  }
  this->Image_->Download(total.data(), total.size() * sizeof(float));
  last.Download(k.data(), k.size() * sizeof(float));
  before.Download(k1.data(), k1.size() * sizeof(float));
  double sumK[3] = { 0, 0, 0 }, sumK1[3] = { 0, 0, 0 };
  for (size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      sumK[c] += k[4 * i + c];
      sumK1[c] += k1[4 * i + c];
    }
  }
  const double N = double(events);
  for (int c = 0; c < 3; ++c)
  {
    const double global = sumK1[c] > 0.0 ? std::min(double(maxRatio), sumK[c] / sumK1[c]) : 0.0;
    for (size_t i = 0; i < n; ++i)
    {
      const double ik = k[4 * i + c], ik1 = k1[4 * i + c];
      const double r = std::max(0.0, ik1 > 0.0 ? std::min(global, ik / ik1) : global);
      // sum_{m=1..N} r^m = r (1 - r^N) / (1 - r), r < 1
      const double series = r * (1.0 - std::pow(r, N)) / (1.0 - r);
      total[4 * i + c] += float(ik * series);
      for (size_t a = 0; !moment.empty() && a < 3; ++a)
      {
        moment[4 * (a * n + i) + c] += float(momentK[4 * (a * n + i) + c] * series);
      }
    }
  }
  this->Image_->Upload(total.data(), total.size() * sizeof(float));
  if (!moment.empty())
  {
    this->Moment_->Upload(moment.data(), moment.size() * sizeof(float));
  }
}

std::vector<float> LightVolume::DownloadMoment() const
{
  std::vector<float> out;
  if (!this->Moment())
  {
    return out;
  }
  out.resize(size_t(4) * this->Moment_->Width() * this->Moment_->Height() * this->Moment_->Depth());
  this->Moment_->Download(out.data(), out.size() * sizeof(float));
  return out;
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
