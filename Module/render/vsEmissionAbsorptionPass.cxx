#include "vsEmissionAbsorptionPass.h"
#include "sampling/bindings.h"
#include "sampling/sphere.h"
#include "vsRenderTargetLimits.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_ea_render.h"

#include <cmath>

namespace vs
{
namespace
{
// Keeps a buffer at least `bytes` large, reallocating only when it grows.
void Reserve(std::unique_ptr<Buffer>& b, const std::shared_ptr<Context>& ctx, uint64_t bytes, const char* name)
{
  if (!b || b->Size() < bytes)
  {
    b.reset();
    b = std::make_unique<Buffer>(ctx, bytes, name);
  }
}
}

EmissionAbsorptionPass::EmissionAbsorptionPass(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

const ComputePipeline& EmissionAbsorptionPass::PipelineFor(
  bool factor, bool shade, uint32_t lighting, bool projection, bool display, bool lights, uint32_t anisotropic)
{
  // The preview's shading is the surface lobe (issue 38); ambient occlusion is not shaded.
  shade = shade && lighting != shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION;
  const std::array<uint32_t, 7> constants = { factor ? 1u : 0u, shade ? 1u : 0u, lighting, projection ? 1u : 0u,
    display ? 1u : 0u, lights ? 1u : 0u, anisotropic };
  auto& pipeline = this->Pipelines_[constants];
  if (!pipeline)
  {
    // SharedPipeline shares by name: one name per set of constants.
    std::string name = lighting == shared::VS_EA_LIGHTING_PREVIEW ? "preview"
      : lighting == shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION     ? "ambient occlusion"
                                                                  : "emission-absorption";
    const char* shaded = lighting == shared::VS_EA_LIGHTING_PREVIEW ? "surface lobe" : "shaded";
    name += factor ? (shade ? std::string(" (gradient opacity, ") + shaded + ")" : std::string(" (gradient opacity)"))
                   : (shade ? std::string(" (") + shaded + ")" : std::string());
    name += projection ? ", projections" : "";
    name += display ? ", with its window image" : "";
    name += lights ? ", VTK's lights" : "";
    name += anisotropic == 2u ? ", anisotropic towards the environment, two lobes"
      : anisotropic           ? ", anisotropic towards the environment"
                              : "";
    pipeline = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_ea_render),
      BindingTypes(shared::VS_EA_BINDING_COUNT,
        { { shared::VS_EA_VOLUME, BindingType::StorageImage }, { shared::VS_EA_TF, BindingType::UniformTexelBuffer },
          { shared::VS_EA_PARAMS, BindingType::StorageBuffer }, { shared::VS_EA_DEPTH, BindingType::UniformTexelBuffer },
          { shared::VS_EA_RESULT, BindingType::StorageBuffer },
          { shared::VS_EA_FACTOR_IMAGE, BindingType::StorageImage },
          { shared::VS_EA_LIGHT, BindingType::StorageImage }, { shared::VS_EA_BRICKS, BindingType::StorageImage },
          { shared::VS_EA_ENVIRONMENT, BindingType::UniformTexelBuffer },
          { shared::VS_EA_DISPLAY, BindingType::StorageBuffer },
          { shared::VS_EA_LIGHT_TRANSMITTANCE, BindingType::StorageImage },
          { shared::VS_EA_LIGHT_MOMENT, BindingType::StorageImage } }),
      0, name, std::vector<uint32_t>(constants.begin(), constants.end()));
  }
  return *pipeline;
}

EmissionAbsorptionPass::~EmissionAbsorptionPass() = default;

// Rows of 16 bytes (volume_params.h): a member that breaks the rule changes the size.
static_assert(sizeof(shared::VsEmissionAbsorptionParams) ==
    sizeof(shared::VsCameraParams) + sizeof(shared::VsVolumeParams) + 4 * 16 + sizeof(shared::VsGridParams) + 16 + 3 * 16 +
      shared::VS_MAX_SCENE_LIGHTS * sizeof(shared::VsSceneLight),
  "VsEmissionAbsorptionParams: rows of 16 bytes (volume_params.h)");

std::vector<float> EmissionAbsorptionPass::Render(const DeviceVolume& volume,
  const TransferFunctionTable& tf, const MajorantGrid* majorants, const shared::VsEmissionAbsorptionParams& inParams, const std::vector<float>& depth,
  bool shade, uint32_t lighting, const Image3D* light, const Buffer* environment, const Image3D* lightTransmittance,
  const Image3D* lightMoment)
{
  this->LastDisplay_.clear();
  if (lighting > shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION)
  {
    throw InputError("unknown lighting of the emission-absorption pass: " + std::to_string(lighting));
  }
  shared::VsEmissionAbsorptionParams params = inParams;
  params.volume.majorantBricks = glm::uvec3(0u);
  params.volume.majorantBrickSize = 0.0f;
  if (majorants)
  {
    const auto b = majorants->Bricks();
    params.volume.majorantBricks = glm::uvec3(b[0], b[1], b[2]);
    params.volume.majorantBrickSize = float(majorants->BrickSize());
  }
  if (lighting != shared::VS_EA_LIGHTING_NONE)
  {
    if (light)
    {
      const glm::uvec3 c = params.grid.cells;
      if (light->Width() != c.x || light->Height() != c.y || light->Depth() != c.z || c.x == 0 || c.y == 0 || c.z == 0)
      {
        throw InputError("the light volume (" + std::to_string(light->Width()) + " x " + std::to_string(light->Height()) +
          " x " + std::to_string(light->Depth()) + ") does not match the grid's cells (" + std::to_string(c.x) + " x " +
          std::to_string(c.y) + " x " + std::to_string(c.z) + ")");
      }
    }
    else
    {
      params.grid.cells = glm::uvec3(1u);
      params.grid.cellSize = glm::max(params.volume.boxMax - params.volume.boxMin, glm::vec3(1e-30f));
    }
  }
  if (params.lightCount > shared::VS_MAX_SCENE_LIGHTS)
  {
    throw InputError("the emission-absorption pass takes at most " + std::to_string(shared::VS_MAX_SCENE_LIGHTS) +
      " lights, got " + std::to_string(params.lightCount));
  }
  if (lighting == shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION || (lighting == shared::VS_EA_LIGHTING_NONE && !shade))
  {
    params.lightCount = 0u; // unread
  }
  if (lighting == shared::VS_EA_LIGHTING_PREVIEW && params.lightCount > 0u)
  {
    if (!light)
    {
      params.lightCount = 0u; // a volume without extinction: transparent anyway
    }
    else if (!lightTransmittance || lightTransmittance->Width() != light->Width() ||
      lightTransmittance->Height() != light->Height() || lightTransmittance->Depth() != 2 * light->Depth())
    {
      throw InputError("the preview's " + std::to_string(params.lightCount) +
        " lights need the light volume's transmittance towards them, of the light volume's cells with 2 layers");
    }
  }
  // The phase's band 1 towards the environment (issue 39): the preview with g != 0 and the moment.
  const bool anisotropic = lighting == shared::VS_EA_LIGHTING_PREVIEW && light && lightMoment &&
    std::abs(params.anisotropy) >= shared::VS_HG_ISOTROPIC_G;
  if (anisotropic &&
    (lightMoment->Width() != light->Width() || lightMoment->Height() != light->Height() ||
      (lightMoment->Depth() != 3 * light->Depth() && lightMoment->Depth() != 6 * light->Depth())))
  {
    throw InputError("the preview's band-1 moment must have the light volume's cells with 3 or 6 layers");
  }
  if ((params.display & shared::VS_EA_DISPLAY_ENVIRONMENT) != 0u)
  {
    const uint64_t n = params.environmentSize;
    if (!environment || n == 0 || environment->Size() < n * n * 4 * sizeof(float))
    {
      throw InputError("the emission-absorption pass was asked for the environment behind the volume without an "
                       "environment map of " + std::to_string(n) + " x " + std::to_string(n) + " texels");
    }
  }
  const bool display = (params.display & shared::VS_EA_DISPLAY_IMAGE) != 0u;
  const uint32_t w = params.camera.width, h = params.camera.height;
  if (w == 0 || h == 0)
  {
    return {};
  }
  RenderTargetLimits::Check(*this->Context_, w, h);
  const uint64_t pixels = uint64_t(w) * h;
  if (!depth.empty() && depth.size() != pixels)
  {
    throw InputError("depth buffer has " + std::to_string(depth.size()) + " values for " +
      std::to_string(pixels) + " pixels");
  }
  Reserve(this->Params_, this->Context_, sizeof(params), "frame parameters");
  Reserve(this->Depth_, this->Context_, pixels * sizeof(float), "depth");
  Reserve(this->Out_, this->Context_, pixels * 4 * sizeof(float), "emission-absorption image");
  if (display)
  {
    Reserve(this->Display_, this->Context_, pixels * 4 * sizeof(float), "emission-absorption window image");
  }
  this->Params_->Upload(&params, sizeof(params));
  if (depth.empty())
  {
    std::vector<float> ones(pixels, 1.0f);
    this->Depth_->Upload(ones.data(), pixels * sizeof(float));
  }
  else
  {
    this->Depth_->Upload(depth.data(), pixels * sizeof(float));
  }
  if (!this->NoLight_)
  {
    this->NoLight_ = std::make_unique<Image3D>(this->Context_, 1, 1, 1, vk::Format::eR32G32B32A32Sfloat, "no light");
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    this->NoLight_->Upload(zero, sizeof(zero));
  }
  const ComputePipeline& pipeline = this->PipelineFor(volume.Factor() != nullptr, shade, lighting,
    params.blend != shared::VS_BLEND_COMPOSITE, display, params.lightCount > 0u,
    anisotropic ? (lightMoment->Depth() == 6 * light->Depth() ? 2u : 1u) : 0u);
  DescriptorSet set(pipeline);
  set.Bind(shared::VS_EA_VOLUME, volume.Image())
    .BindTexels(shared::VS_EA_TF, tf.Lut(), vk::Format::eR32G32B32A32Sfloat)
    .Bind(shared::VS_EA_PARAMS, *this->Params_)
    .BindTexels(shared::VS_EA_DEPTH, *this->Depth_, vk::Format::eR32Sfloat)
    .Bind(shared::VS_EA_RESULT, *this->Out_);
  set.Bind(shared::VS_EA_FACTOR_IMAGE, volume.Factor() ? *volume.Factor() : volume.Image()); // unread without a factor
  set.Bind(shared::VS_EA_LIGHT, lighting != shared::VS_EA_LIGHTING_NONE && light ? *light : *this->NoLight_);
  set.Bind(shared::VS_EA_BRICKS, majorants ? majorants->TrackingImage() : *this->NoLight_);
  // Placeholders where unread: the transfer function's texels, the radiance image.
  if (environment)
  {
    set.BindTexels(shared::VS_EA_ENVIRONMENT, *environment, vk::Format::eR32G32B32A32Sfloat);
  }
  else
  {
    set.BindTexels(shared::VS_EA_ENVIRONMENT, tf.Lut(), vk::Format::eR32G32B32A32Sfloat);
  }
  set.Bind(shared::VS_EA_DISPLAY, display ? *this->Display_ : *this->Out_);
  set.Bind(shared::VS_EA_LIGHT_TRANSMITTANCE,
    lighting == shared::VS_EA_LIGHTING_PREVIEW && params.lightCount > 0u ? *lightTransmittance : *this->NoLight_);
  set.Bind(shared::VS_EA_LIGHT_MOMENT, anisotropic ? *lightMoment : *this->NoLight_);
  Batch batch(this->Context_);
  batch.BeginTimer("render");
  batch.Dispatch(pipeline, set, nullptr, 0, (w + 7) / 8, (h + 7) / 8, 1);
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ = batch.Seconds("render");
  std::vector<float> result(pixels * 4);
  this->Out_->Download(result.data(), result.size() * sizeof(float));
  if (display)
  {
    this->LastDisplay_.resize(pixels * 4);
    this->Display_->Download(this->LastDisplay_.data(), this->LastDisplay_.size() * sizeof(float));
  }
  return result;
}
}
