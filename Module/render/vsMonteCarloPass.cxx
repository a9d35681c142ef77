#include "vsMonteCarloPass.h"
#include "sampling/bindings.h"
#include "sampling/kernel_spec.h"
#include "sampling/strategies.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsDeviceVolume.h"
#include "vsDirectionTable.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsKernelOptions.h"
#include "vsMajorantGrid.h"
#include "vsPipeline.h"
#include "vsRenderTargetLimits.h"
#include "vsSceneLightParams.h"
#include "vsSurfaceScattering.h"
#include "vsTransferFunctionTable.h"
#include "vsVisibilityGrid.h"

#include "vs_spirv_mc_render_count.h"
#include "vs_spirv_mc_render_env.h"
#include "vs_spirv_mc_render_march_r16.h"
#include "vs_spirv_mc_render_march_r32f.h"
#include "vs_spirv_mc_render_march_r8.h"
#include "vs_spirv_mc_render_r16.h"
#include "vs_spirv_mc_render_r32f.h"
#include "vs_spirv_mc_render_r8.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace vs
{
namespace
{
// The sample loop's budget on a driver without a loop limiter: none in practice (a dispatch's
// samples stay far below it), and small enough that the kernel's cost + sampleMax cannot wrap.
constexpr uint32_t NoLoopBudget = 1u << 30;
}

MonteCarloPass::MonteCarloPass(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

MonteCarloPass::~MonteCarloPass() = default;

const ComputePipeline& MonteCarloPass::PipelineFor(
  const VisibilityGrid* grid, const shared::VsMonteCarloParams& params, bool refine, bool table, bool quads)
{
  vk::Format f = grid && grid->Valid() ? grid->Image().Format() : vk::Format::eR8Unorm;
  int format = f == vk::Format::eR8Unorm ? 0 : f == vk::Format::eR16Unorm ? 1 : 2;
  if (this->CountLookups_)
  {
    if (format != 0)
    {
      throw InputError("counting reads needs the r8 visibility grid (the default storage format)");
    }
    format = 3;
  }
  const uint32_t strategy = params.strategy;
  // The cell mode matters only where a grid is read: one pipeline for Uniform and Environment.
  const uint32_t cellMode =
    strategy > shared::VS_STRATEGY_ENVIRONMENT ? params.cellMode : uint32_t(shared::VS_CELL_STOCHASTIC);
  if (strategy > shared::VS_STRATEGY_TWO_STEP)
  {
    throw InputError("unknown sampling strategy " + std::to_string(strategy));
  }
  const uint32_t camera = params.cameraEstimator != shared::VS_CAMERA_COLLISION ? shared::VS_CAMERA_RESERVOIR : shared::VS_CAMERA_COLLISION;
  const uint32_t interpolation = params.volume.interpolation, cropping = params.volume.cropFlags != 0u ? 1u : 0u;
  const bool defensive = Defensive(params);
  // Hidden cropping regions have no extinction, below any brick's control: no control there.
  const uint32_t control = cropping ? 0u : params.controlExtinction & (shared::VS_CONTROL_SHADOW | shared::VS_CONTROL_CAMERA);
  const uint32_t factor = params.volume.extinctionFactor != 0u ? 1u : 0u; // the gradient opacity's factor volume
  const uint32_t transmittance =
    params.transmittance != shared::VS_TRANSMITTANCE_RATIO_TRACKING ? shared::VS_TRANSMITTANCE_RAY_MARCHING : shared::VS_TRANSMITTANCE_RATIO_TRACKING;
  // Environment and Uniform without counting or ray marching: the module without the grid's code
  // (mc_render_env.comp), whatever the grid's format (it binds no grid).
  if (format != 3 && strategy <= shared::VS_STRATEGY_ENVIRONMENT && transmittance == shared::VS_TRANSMITTANCE_RATIO_TRACKING)
  {
    format = 4;
  }
  const uint32_t sampler = params.pixelSampler == shared::VS_SAMPLER_SOBOL ? shared::VS_SAMPLER_SOBOL : shared::VS_SAMPLER_INDEPENDENT;
  KernelSpecialization spec;
  spec.Set(shared::VS_SPEC_ID_STRATEGY, strategy)
    .Set(shared::VS_SPEC_ID_CELL_MODE, cellMode)
    .Set(shared::VS_SPEC_ID_REFINE, refine ? 1u : 0u)
    .Set(shared::VS_SPEC_ID_CAMERA, camera)
    .Set(shared::VS_SPEC_ID_INTERPOLATION, interpolation)
    .Set(shared::VS_SPEC_ID_CROPPING, cropping)
    .Set(shared::VS_SPEC_ID_TABLE, table ? 1u : 0u)
    .Set(shared::VS_SPEC_ID_DEFENSIVE, defensive ? 1u : 0u)
    .Set(shared::VS_SPEC_ID_SKIP, this->EmptySpaceSkipping_ ? 1u : 0u)
    .Set(shared::VS_SPEC_ID_QUADS, quads ? 1u : 0u)
    .Set(shared::VS_SPEC_ID_CONTROL, control)
    .Set(shared::VS_SPEC_ID_SAMPLER, sampler)
    .Set(shared::VS_SPEC_ID_FACTOR, factor)
    .Set(shared::VS_SPEC_ID_TRANSMITTANCE, transmittance)
    .Set(shared::VS_SPEC_ID_PATH, FullTransport(params) ? 1u : 0u)
    // The loop budget only where the driver has a loop limiter (lavapipe's), from its driver id.
    .Set(shared::VS_SPEC_ID_LOOP_BUDGET, this->Context_->Info().LoopLimited() ? shared::VS_LOOP_BUDGET : NoLoopBudget)
    // Hybrid scattering (vsSurfaceScattering.h) and VTK's lights (vsSceneLightParams.h), issue 38.
    .Set(shared::VS_SPEC_ID_SURFACE, SurfaceScattering::Enabled(params) ? 1u : 0u)
    .Set(shared::VS_SPEC_ID_LIGHTS, SceneLightParams::Enabled(params) ? 1u : 0u);
  const std::vector<uint32_t> specialization = spec.Values();
  // A bounded set of variants (a host that churns settings would otherwise hold every pipeline it
  // ever used: issue 35, class 10): the least recently used goes, and the context's cache lets its
  // pipelines go once nothing holds them.
  if (this->Pipelines_.find(specialization) == this->Pipelines_.end() &&
    this->Pipelines_.size() >= kMaxPipelineVariants)
  {
    auto oldest = this->Pipelines_.begin();
    for (auto it = this->Pipelines_.begin(); it != this->Pipelines_.end(); ++it)
    {
      if (this->PipelineUse_[it->first] < this->PipelineUse_[oldest->first])
      {
        oldest = it;
      }
    }
    this->PipelineUse_.erase(oldest->first);
    this->Pipelines_.erase(oldest);
  }
  this->PipelineUse_[specialization] = ++this->PipelineClock_;
  auto& slot = this->Pipelines_[specialization];
  auto& pipeline = slot[format];
  if (!pipeline)
  {
    const std::vector<BindingType> bindings = KernelBindings();
    static const char* formats[] = { "r8 visibility", "r16 visibility", "r32f visibility",
      "r8 visibility, counting reads", "no grid" };
    const std::string name = std::string("monte carlo (") + formats[format] + ", " +
      KernelOptionWord(KernelOptionId::Strategy, strategy) + ", " +
      (cellMode == shared::VS_CELL_STOCHASTIC ? "stochastic cell" : "trilinear cells") +
      (refine ? ", cell walk" : "") + (camera == shared::VS_CAMERA_RESERVOIR ? ", reservoir camera" : "") +
      (interpolation != 0u ? ", nearest" : "") + (cropping ? ", cropping regions" : "") +
      (table ? ", direction table" : "") + (defensive ? ", defensive" : "") +
      (this->EmptySpaceSkipping_ ? "" : ", no empty-space skipping") + (quads ? ", 8-bit quads" : "") +
      (transmittance == shared::VS_TRANSMITTANCE_RAY_MARCHING ? ", ray-marched shadow rays"
          : (control & shared::VS_CONTROL_SHADOW) ? ", residual ratio tracking" : "") +
      ((control & shared::VS_CONTROL_CAMERA) ? ", decomposition tracking" : "") +
      (sampler == shared::VS_SAMPLER_SOBOL ? ", Sobol" : "") + (factor ? ", gradient opacity" : "") +
      (FullTransport(params) ? ", full transport" : "") +
      (SurfaceScattering::Enabled(params) ? ", surface scattering" : "") +
      (SceneLightParams::Enabled(params) ? ", scene lights" : "") + ")";
    if (format == 4)
    {
      pipeline = SharedPipeline(
        this->Context_, VS_SPIRV(vs_spirv_mc_render_env), bindings, sizeof(uint32_t), name, specialization);
    }
    else if (format == 3)
    {
      pipeline = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_mc_render_count), bindings, sizeof(uint32_t), name,
        specialization);
    }
    else if (transmittance == shared::VS_TRANSMITTANCE_RAY_MARCHING)
    {
      // Ray marching lives in modules of its own (mc_render.glsl, VS_RAY_MARCHING).
      pipeline = format == 0
        ? SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_mc_render_march_r8), bindings, sizeof(uint32_t), name,
            specialization)
        : format == 1 ? SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_mc_render_march_r16), bindings,
                          sizeof(uint32_t), name, specialization)
                      : SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_mc_render_march_r32f), bindings,
                          sizeof(uint32_t), name, specialization);
    }
    else if (format == 0)
      pipeline = SharedPipeline(
        this->Context_, VS_SPIRV(vs_spirv_mc_render_r8), bindings, sizeof(uint32_t), name, specialization);
    else if (format == 1)
      pipeline = SharedPipeline(
        this->Context_, VS_SPIRV(vs_spirv_mc_render_r16), bindings, sizeof(uint32_t), name, specialization);
    else
      pipeline = SharedPipeline(
        this->Context_, VS_SPIRV(vs_spirv_mc_render_r32f), bindings, sizeof(uint32_t), name, specialization);
  }
  return *pipeline;
}

std::vector<BindingType> MonteCarloPass::KernelBindings()
{
  using B = BindingType;
  return BindingTypes(shared::VS_MC_BINDING_COUNT,
    { { shared::VS_MC_VOLUME, B::StorageImage }, { shared::VS_MC_TF, B::UniformTexelBuffer },
      { shared::VS_MC_BRICKS, B::StorageImage }, { shared::VS_MC_VISIBILITY, B::StorageImage },
      { shared::VS_MC_PARAMS, B::StorageBuffer }, { shared::VS_MC_ENV, B::UniformTexelBuffer },
      { shared::VS_MC_MIPS, B::UniformTexelBuffer }, { shared::VS_MC_DEPTH, B::StorageBuffer },
      { shared::VS_MC_SUM, B::StorageBuffer }, { shared::VS_MC_COMPENSATION, B::StorageBuffer },
      { shared::VS_MC_SQUARES, B::StorageBuffer }, { shared::VS_MC_PROGRESS, B::StorageBuffer },
      { shared::VS_MC_TABLE, B::UniformTexelBuffer }, { shared::VS_MC_RETIRED, B::StorageImage },
      { shared::VS_MC_LOOKUPS, B::StorageBuffer }, { shared::VS_MC_QUADS, B::StorageImage },
      { shared::VS_MC_FACTOR_IMAGE, B::StorageImage }, { shared::VS_MC_PATH_POSITION, B::StorageBuffer },
      { shared::VS_MC_PATH_DIRECTION, B::StorageBuffer }, { shared::VS_MC_PATH_THROUGHPUT, B::StorageBuffer },
      { shared::VS_MC_PATH_RADIANCE, B::StorageBuffer } });
}

void MonteCarloPass::Prewarm(const shared::VsMonteCarloParams& params, bool table, bool quads, bool cellWalk)
{
  // As Render decides: nearest interpolation reads the float image even where the volume has quads.
  const bool readsQuads = quads && this->VolumeQuads_ && params.volume.interpolation == 0u;
  this->PipelineFor(nullptr, params, cellWalk, table && params.strategy > shared::VS_STRATEGY_ENVIRONMENT, readsQuads);
}

bool MonteCarloPass::FullTransport(const shared::VsMonteCarloParams& params)
{
  // Exactly single scattering with the isotropic phase keeps the single-scattering estimator (its
  // images are those of the kernel before full transport, bit for bit).
  return params.maxEvents > 1u || params.anisotropy != 0.0f ||
    SurfaceScattering::Enabled(params) || SceneLightParams::Enabled(params); // issue 38: in the path kernel
}

void MonteCarloPass::CheckScattering(const shared::VsMonteCarloParams& params)
{
  CheckScatteringSettings(double(params.maxEvents), double(params.anisotropy));
  if (params.mis > shared::VS_MIS_BALANCE)
  {
    throw InputError("unknown multiple importance sampling mode " + std::to_string(params.mis));
  }
}

bool MonteCarloPass::Defensive(const shared::VsMonteCarloParams& params)
{
  return params.strategy == shared::VS_STRATEGY_TWO_STEP && params.defensiveWeight > 0.0f;
}

bool MonteCarloPass::NeedsCellWalk(const MajorantGrid& majorants, const shared::VsMonteCarloParams& params)
{
  return NeedsCellWalk(double(majorants.MaxMajorant()), majorants.BrickSize(), params);
}

bool MonteCarloPass::NeedsCellWalk(double maxMajorant, uint32_t brickSize, const shared::VsMonteCarloParams& params)
{
  // The longest world-space path through a brick: its index-space diagonal (B sqrt 3) through the
  // index-to-world matrix, bounded by the matrix's Frobenius norm (>= its largest singular value).
  const glm::mat3 indexToWorld = glm::inverse(glm::mat3(params.volume.worldToIndex));
  double norm2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      norm2 += double(indexToWorld[c][r]) * indexToWorld[c][r];
    }
  }
  const double longest = brickSize * std::sqrt(3.0) * std::sqrt(norm2);
  const double depth = params.cellWalkDepth > 0.0f ? params.cellWalkDepth : 32.0;
  const double worst = maxMajorant * longest;
  // 0.1% for the trackers' shortest step past a face; non-finite (a singular matrix, an infinite
  // majorant) keeps the cell walk: it is the safe side.
  return !(worst * 1.001 <= depth);
}

void MonteCarloPass::Reset(uint32_t width, uint32_t height)
{
  const uint64_t pixels = uint64_t(width) * height;
  if (pixels == 0)
  {
    throw InputError("an image of zero pixels");
  }
  RenderTargetLimits::Check(*this->Context_, width, height);
  if (width != this->Width_ || height != this->Height_ || !this->Sum_)
  {
    this->Sum_.reset();
    this->Comp_.reset();
    this->PathPosition_.reset();
    this->PathDirection_.reset();
    this->PathThroughput_.reset();
    this->PathRadiance_.reset();
    this->Squares_.reset();
    this->Depth_.reset();
    this->Progress_.reset();
    this->Sum_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "radiance sum");
    this->Comp_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "radiance compensation");
    this->Squares_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "radiance squares");
    this->Depth_ = std::make_unique<Buffer>(this->Context_, pixels * 4, "depth");
    // Samples per pixel, then the count of pixels a dispatch left short of its target.
    // and the scattering events of a Render's paths (full transport).
    this->Progress_ = std::make_unique<Buffer>(this->Context_, (pixels + 2) * 4, "samples per pixel");
    this->LastDepth_.clear();
  }
  if (this->PathPosition_)
  {
    this->PathPosition_->Fill(0u); // no path in flight
  }
  this->Sum_->Fill(0u);
  this->Comp_->Fill(0u);
  this->Squares_->Fill(0u);
  this->Progress_->Fill(0u);
  this->Width_ = width;
  this->Height_ = height;
  this->Samples_ = 0;
  this->TotalSeconds_ = 0.0;
  this->Events_ = 0;
}

void MonteCarloPass::Render(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const VisibilityGrid* grid, const DeviceEnvironment& environment,
  shared::VsMonteCarloParams params, const std::vector<float>& depth)
{
  if (params.camera.width != this->Width_ || params.camera.height != this->Height_ || !this->Sum_)
  {
    throw InputError("MonteCarloPass::Render for a size the accumulators were not reset to");
  }
  const uint64_t pixels = uint64_t(this->Width_) * this->Height_;
  if (!depth.empty() && depth.size() != pixels)
  {
    throw InputError("depth buffer has " + std::to_string(depth.size()) + " values for " + std::to_string(pixels) +
      " pixels");
  }
  if (depth != this->LastDepth_ || this->LastDepth_.empty())
  {
    this->LastDepth_ = depth.empty() ? std::vector<float>(pixels, 1.0f) : depth;
    this->Depth_->Upload(this->LastDepth_.data(), pixels * 4);
  }
  if (params.maxEvents == 0u)
  {
    params.maxEvents = 1u; // 0: the parameters' zero value, single scattering
  }
  CheckScattering(params);
  SurfaceScattering::Check(params); // issue 38
  SceneLightParams::Check(params);
  if (SurfaceScattering::Enabled(params))
  {
    // issue 38: the reservoir camera's event weight is not an albedo the surface lobe could colour.
    params.cameraEstimator = shared::VS_CAMERA_COLLISION;
  }
  const bool fullTransport = FullTransport(params);
  if (fullTransport && !this->PathPosition_)
  {
    // The paths in flight between dispatches (path_state.glsl): 4 x 16 bytes per pixel, checked
    // against the device's limits as the accumulators are (RenderTargetLimits).
    this->PathPosition_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "paths in flight: positions");
    this->PathDirection_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "paths in flight: directions");
    this->PathThroughput_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "paths in flight: throughputs");
    this->PathRadiance_ = std::make_unique<Buffer>(this->Context_, pixels * 16, "paths in flight: radiance");
    this->PathPosition_->Fill(0u);
  }
  if (!this->NoPaths_)
  {
    this->NoPaths_ = std::make_unique<Buffer>(this->Context_, 16, "no paths in flight");
  }
  if (!(params.defensiveWeight >= 0.0f && params.defensiveWeight <= 1.0f))
  {
    throw InputError("TwoStep's defensive weight must be in [0, 1], got " + std::to_string(params.defensiveWeight));
  }
  // Environment and Uniform read no grid (their module has none: mc_render_env.comp).
  const bool useGrid =
    grid && grid->Valid() && params.grid.side > 0 && params.strategy > shared::VS_STRATEGY_ENVIRONMENT;
  if (!useGrid)
  {
    params.grid.cells = glm::uvec3(1u);
    params.grid.side = 0u;
    if (!this->NoGrid_)
    {
      this->NoGrid_ = std::make_unique<Image3D>(this->Context_, 1, 1, 1, vk::Format::eR8Unorm, "no visibility grid");
    }
  }
  else
  {
    // While the grid fills in, unswept directions read swept ones (VisibilityGrid::RedirectDirections).
    const std::vector<uint32_t>& sources = grid->DirectionSources();
    if (sources.size() != size_t(params.grid.side) * params.grid.side || sources.size() > shared::VS_MAX_RENDER_DIRECTIONS)
    {
      throw InputError("the render kernel reads grids of up to 16 x 16 directions, matching the parameters' D; got " +
        std::to_string(sources.size()) + " directions for D " + std::to_string(params.grid.side));
    }
    for (uint32_t n = 0; n < shared::VS_MAX_RENDER_DIRECTIONS; ++n)
    {
      params.directionSources[n / 4u][n % 4u] = n < sources.size() ? sources[n] : n;
    }
  }
  params.camera.frame = this->Samples_;
  const bool quads = this->VolumeQuads_ && volume.Quads() && params.volume.interpolation == 0u;
  params.volume.quadZero = quads ? volume.QuadOffset() : 0.0f;
  params.volume.extinctionFactor = volume.Factor() ? 1u : 0u; // the kernel's VS_SPEC_FACTOR
  this->LastUsedQuads_ = quads;
  if (!this->Params_)
  {
    this->Params_ = std::make_unique<Buffer>(this->Context_, sizeof(params), "render parameters");
  }
  this->Params_->Upload(&params, sizeof(params));

  if (!useGrid && params.strategy > shared::VS_STRATEGY_ENVIRONMENT)
  {
    params.strategy = shared::VS_STRATEGY_UNIFORM; // what the kernel does without a grid (D = 0)
  }
  // The grid strategies under stochastic cells read the cells' direction table, made (or kept)
  // for this grid, environment and strategy here.
  const uint32_t strategy = params.strategy;
  bool table = false;
  this->LastTableSeconds_ = 0.0;
  if (useGrid && this->UseTable_ && strategy > shared::VS_STRATEGY_ENVIRONMENT &&
    params.cellMode == shared::VS_CELL_STOCHASTIC)
  {
    if (!this->Table_)
    {
      this->Table_ = std::make_shared<DirectionTable>(this->Context_);
    }
    const float epsilon = params.visibilityEpsilon;
    DirectionTable& t = *this->Table_;
    const bool rebuild = !t.Usable(*grid, environment, strategy, epsilon) ||
      (!t.Current(*grid, environment, strategy, epsilon) &&
        t.SecondsUsed() >= this->TableRebuildRatio_ * t.LastSeconds());
    if (rebuild)
    {
      const uint64_t builds = t.Builds();
      table = t.Update(*grid, environment, strategy, epsilon);
      if (t.Builds() != builds)
      {
        this->LastTableSeconds_ = t.LastSeconds();
      }
    }
    else
    {
      table = true;
    }
  }
  this->LastUsedTable_ = table;
  if (!this->NoTable_)
  {
    this->NoTable_ = std::make_unique<Buffer>(this->Context_, 16, "no direction table");
  }
  const ComputePipeline& pipeline =
    this->PipelineFor(useGrid ? grid : nullptr, params, NeedsCellWalk(majorants, params), table, quads);
  this->LastPipelineName_ = pipeline.Name();
  // The kernel reading the quads reads no float (kernel_volume.glsl): the volume's float image is not
  // asked for, so an integer-coded volume never makes it for a render (DeviceVolume::Image()).
  if (quads && !this->NoVolume_)
  {
    this->NoVolume_ = std::make_unique<Image3D>(this->Context_, 1, 1, 1, vk::Format::eR32Sfloat, "no float volume");
  }
  const Image3D& floats = quads ? *this->NoVolume_ : volume.Image();
  DescriptorSet set(pipeline);
  set.Bind(shared::VS_MC_VOLUME, floats)
    .BindTexels(shared::VS_MC_TF, tf.Lut(), vk::Format::eR32Sfloat)
    .Bind(shared::VS_MC_BRICKS, majorants.TrackingImage())
    .Bind(shared::VS_MC_VISIBILITY, useGrid ? grid->Image() : *this->NoGrid_)
    .Bind(shared::VS_MC_PARAMS, *this->Params_)
    .BindTexels(shared::VS_MC_ENV, environment.Radiance(), vk::Format::eR32G32B32A32Sfloat)
    .BindTexels(shared::VS_MC_MIPS, environment.Mips(), vk::Format::eR32Sfloat)
    .Bind(shared::VS_MC_DEPTH, *this->Depth_)
    .Bind(shared::VS_MC_SUM, *this->Sum_)
    .Bind(shared::VS_MC_COMPENSATION, *this->Comp_)
    .Bind(shared::VS_MC_SQUARES, *this->Squares_)
    .Bind(shared::VS_MC_PROGRESS, *this->Progress_)
    .BindTexels(shared::VS_MC_TABLE, table ? this->Table_->Nodes() : *this->NoTable_, vk::Format::eR32Uint);
  if (!quads && !this->NoQuads_)
  {
    this->NoQuads_ = std::make_unique<Image3D>(this->Context_, 1, 1, 1, vk::Format::eR32Uint, "no volume quads");
  }
  set.Bind(shared::VS_MC_QUADS, quads ? *volume.Quads() : *this->NoQuads_);
  set.Bind(shared::VS_MC_FACTOR_IMAGE, volume.Factor() ? *volume.Factor() : floats); // unread without a factor
  set.Bind(shared::VS_MC_PATH_POSITION, fullTransport ? *this->PathPosition_ : *this->NoPaths_)
    .Bind(shared::VS_MC_PATH_DIRECTION, fullTransport ? *this->PathDirection_ : *this->NoPaths_)
    .Bind(shared::VS_MC_PATH_THROUGHPUT, fullTransport ? *this->PathThroughput_ : *this->NoPaths_)
    .Bind(shared::VS_MC_PATH_RADIANCE, fullTransport ? *this->PathRadiance_ : *this->NoPaths_);
  if (this->CountLookups_)
  {
    if (!this->Lookups_)
    {
      this->Lookups_ = std::make_unique<Buffer>(this->Context_, 7 * sizeof(uint32_t), "read counters");
    }
    this->Lookups_->Fill(0u);
    set.Bind(shared::VS_MC_LOOKUPS, *this->Lookups_);
  }
  // Each dispatch brings every pixel towards a target count, SamplesPerDispatch more than the
  // last; a pixel the kernel's loop budget left short (mc_render.glsl) catches up in the next one.
  // The image does not depend on the split.
  const uint32_t chunk = std::max<uint32_t>(1u, this->SamplesPerDispatch_);
  const uint32_t goal = this->Samples_ + params.samplesPerFrame;
  const uint64_t counterOffset = pixels * 4;
  const uint32_t zero = 0;
  const uint32_t groupsX = (this->Width_ + 7) / 8, groupsY = (this->Height_ + 7) / 8;
  this->LastSeconds_ = this->LastTableSeconds_;
  this->LastCatchUps_ = 0;
  this->Progress_->Upload(&zero, 4, counterOffset + 4); // the events of this Render's paths
  for (uint32_t round = 0;; ++round)
  {
    this->Progress_->Upload(&zero, 4, counterOffset);
    Batch batch(this->Context_);
    batch.BeginTimer("render");
    if (round == 0)
    {
      for (uint32_t s = 0; s < params.samplesPerFrame; s += chunk)
      {
        const uint32_t target = this->Samples_ + std::min(s + chunk, params.samplesPerFrame);
        batch.Dispatch(pipeline, set, &target, sizeof(target), groupsX, groupsY, 1);
        batch.Barrier();
      }
    }
    else
    {
      batch.Dispatch(pipeline, set, &goal, sizeof(goal), groupsX, groupsY, 1);
      batch.Barrier();
    }
    batch.EndTimer();
    batch.Submit();
    this->LastSeconds_ += batch.Seconds("render");
    uint32_t shortPixels = 0;
    this->Progress_->Download(&shortPixels, 4, counterOffset);
    if (shortPixels == 0)
    {
      break;
    }
    // Every round completes at least one sample of every short pixel under single scattering, one
    // path segment under full transport (mc_render.glsl's tracking cap), so a frame takes at most one
    // round per sample, or per event (many shadow rays fit one segment per dispatch); this bound only
    // stops a kernel that breaks that promise.
    const uint64_t rounds = uint64_t(params.samplesPerFrame) * (fullTransport ? params.maxEvents : 1u);
    if (round >= std::max<uint64_t>(kMaxCatchUpRounds, rounds))
    {
      throw Error("the render kernel left " + std::to_string(shortPixels) + " pixels short of " +
        std::to_string(goal) + " samples after " + std::to_string(round) +
        " catch-up dispatches (its loop budget per dispatch, VS_LOOP_BUDGET)");
    }
    this->LastCatchUps_ = round + 1;
  }
  this->TotalSeconds_ += this->LastSeconds_;
  if (fullTransport)
  {
    uint32_t events = 0;
    this->Progress_->Download(&events, 4, counterOffset + 4);
    this->Events_ += events;
  }
  else
  {
    // Single scattering: a path has one event where its camera ray collides, none elsewhere;
    // counted as one per path (an upper bound) rather than paying for a count.
    this->Events_ += pixels * params.samplesPerFrame;
  }
  if (table)
  {
    this->Table_->AddSecondsUsed(this->LastSeconds_ - this->LastTableSeconds_);
  }
  this->Samples_ += params.samplesPerFrame;
  this->SquareScale_ = params.squareScale > 0.0f ? params.squareScale : 1.0f;
  if (this->CountLookups_)
  {
    uint32_t counts[7];
    this->Lookups_->Download(counts, sizeof(counts));
    this->LastLookups_ = { counts[0], counts[1], counts[2] };
    this->LastShadowRays_ = { counts[5], counts[6] };
    this->LastLaneOccupancy_ = counts[4] > 0 ? double(counts[3]) / double(counts[4]) : 1.0;
  }
}

uint64_t MonteCarloPass::DirectionTableBuilds() const
{
  return this->Table_ ? this->Table_->Builds() : 0;
}

std::vector<float> MonteCarloPass::Mean() const
{
  const uint64_t n = uint64_t(this->Width_) * this->Height_ * 4;
  std::vector<float> sum(n, 0.0f);
  if (!this->Sum_ || this->Samples_ == 0)
  {
    return sum;
  }
  this->Sum_->Download(sum.data(), n * 4);
  const float inv = 1.0f / float(this->Samples_);
  for (auto& v : sum)
  {
    v *= inv;
  }
  return sum;
}

std::vector<double> MonteCarloPass::Variance() const
{
  const uint64_t n = uint64_t(this->Width_) * this->Height_ * 4;
  std::vector<double> var(n, 0.0);
  if (!this->Sum_ || this->Samples_ < 2)
  {
    return var;
  }
  std::vector<float> sq(n);
  this->Squares_->Download(sq.data(), n * 4);
  std::vector<float> mean = this->Mean();
  const double N = this->Samples_;
  const double s = this->SquareScale_;
  for (uint64_t i = 0; i < n; ++i)
  {
    const double m = mean[i] * (i % 4 < 3 ? s : 1.0); // the squares are of scaled radiance (not alpha)
    const double v = std::max(0.0, (double(sq[i]) / N - m * m) * N / (N - 1.0));
    var[i] = i % 4 < 3 ? v / (s * s) : v;
  }
  return var;
}

double MonteCarloPass::SquareSum() const
{
  if (!this->Sum_ || this->Samples_ == 0)
  {
    return 0.0;
  }
  const uint64_t n = uint64_t(this->Width_) * this->Height_ * 4;
  std::vector<float> sq(n);
  this->Squares_->Download(sq.data(), n * 4);
  double sum = 0.0;
  for (uint64_t i = 0; i < n; ++i)
  {
    sum += i % 4 < 3 ? double(sq[i]) : 0.0;
  }
  const double s = this->SquareScale_;
  return sum / (3.0 * s * s);
}
}
