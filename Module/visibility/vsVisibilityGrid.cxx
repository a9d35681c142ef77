// vsVisibilityGrid.cxx — VisibilityGrid: its image and layout (Allocate, CheckFits, Clear), the
// direction sources (RedirectDirections), Compute (the plan and the globals every pass reads,
// then the sweeps or the brute-force reference), the brute-force march and Download. The plane
// sweeps themselves are in vsVisibilityGridSweeps.cxx.
#include "vsVisibilityGrid.h"
#include "sampling/bindings.h"
#include "vsSerial.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeParams.h"
#include "sampling/interpolation.h"

#include "vs_spirv_visibility_bruteforce.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>
#include <string>

namespace vs
{
namespace
{
vk::Format ToVk(VisibilityGridParameters::Format f)
{
  switch (f)
  {
    case VisibilityGridParameters::Format::Unorm8:
      return vk::Format::eR8Unorm;
    case VisibilityGridParameters::Format::Unorm16:
      return vk::Format::eR16Unorm;
    default:
      return vk::Format::eR32Sfloat;
  }
}

bool SameLayout(const VisibilityGridParameters& a, const VisibilityGridParameters& b)
{
  return a.DirectionResolution == b.DirectionResolution && a.VoxelsPerCell == b.VoxelsPerCell &&
    a.KernelResolution == b.KernelResolution && a.StepSize == b.StepSize && a.Filtering == b.Filtering &&
    a.FilterAngleFraction == b.FilterAngleFraction && a.Algorithm == b.Algorithm &&
    a.BruteForceSamples == b.BruteForceSamples && a.StorageFormat == b.StorageFormat &&
    a.StopTransmittance == b.StopTransmittance && a.AutoKernelRaysPerCell == b.AutoKernelRaysPerCell &&
    a.Directions == b.Directions && a.ExtinctionPooling == b.ExtinctionPooling && a.MaxPooling == b.MaxPooling &&
    a.NearestInterpolation == b.NearestInterpolation;
}

bool SameGeometry(const VolumeGeometry& a, const VolumeGeometry& b)
{
  // The box too: cropping changes it, and with it the cells' placement.
  return a.Dims == b.Dims && a.WorldToIndex == b.WorldToIndex && a.BoxMin == b.BoxMin && a.BoxMax == b.BoxMax &&
    a.CropFlags == b.CropFlags && (a.CropFlags == 0 || (a.CropLo == b.CropLo && a.CropHi == b.CropHi));
}

struct SlicePush
{
  uint32_t first;
  uint32_t firstDirection;
};
}

VisibilityGrid::VisibilityGrid(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

VisibilityGrid::~VisibilityGrid() = default;

uint64_t VisibilityGrid::Bytes() const
{
  return this->Image_ ? this->Image_->Bytes() : 0;
}

void VisibilityGrid::CheckFits(Context& context, const VolumeGeometry& geometry, const VisibilityGridParameters& p)
{
  p.Validate();
  const uint32_t d = p.DirectionResolution;
  auto cells = SweepPlan::CellCount(geometry, p.VoxelsPerCell, d, context.Info().MaxImageDimension3D);
  Image3D::CheckLimits(context, cells[0] * d, cells[1] * d, cells[2], ToVk(p.StorageFormat), "visibility grid");
  if (!context.Info().WriteWithoutFormat)
  {
    throw DeviceLimitError("the device '" + context.Info().Name +
      "' cannot write storage images without a format (shaderStorageImageWriteWithoutFormat), "
      "which the visibility sweeps need");
  }
}

bool VisibilityGrid::Allocate(
  const VolumeGeometry& geometry, const VisibilityGridParameters& parameters, bool clear, float clearValue)
{
  parameters.Validate();
  if (this->Image_ && SameLayout(parameters, this->Parameters_) && SameGeometry(geometry, this->Geometry_))
  {
    return false;
  }
  const auto& info = this->Context_->Info();
  const uint64_t maxFloats = WorkBufferFloats(info);
  CheckFits(*this->Context_, geometry, parameters);
  this->Image_.reset();
  this->Plan_ = SweepPlan::Make(geometry, parameters, maxFloats, {}, 8, info.MaxImageDimension3D);
  const auto& c = this->Plan_.Cells;
  const uint32_t d = parameters.DirectionResolution;
  this->Image_ = std::make_unique<Image3D>(this->Context_, c[0] * d, c[1] * d, c[2], ToVk(parameters.StorageFormat),
    "visibility grid");
  this->Parameters_ = parameters;
  this->Geometry_ = geometry;
  this->ResetSources();
  if (clear)
  {
    this->Image_->Clear(clearValue);
  }
  this->ContentSerial_ = NewSerial();
  return true;
}

void VisibilityGrid::Clear(float value)
{
  if (!this->Image_)
  {
    throw InputError("the visibility grid has no image to clear");
  }
  this->Image_->Clear(std::clamp(value, 0.0f, 1.0f));
  this->ResetSources();
  this->ContentSerial_ = NewSerial();
}

void VisibilityGrid::ResetSources()
{
  const uint32_t count = this->Parameters_.DirectionResolution * this->Parameters_.DirectionResolution;
  this->Sources_.resize(count);
  for (uint32_t n = 0; n < count; ++n)
  {
    this->Sources_[n] = n;
  }
  this->UploadSources();
}

void VisibilityGrid::UploadSources()
{
  const uint64_t bytes = this->Sources_.size() * sizeof(uint32_t);
  if (!this->SourceBuffer_ || this->SourceBuffer_->Size() != bytes)
  {
    this->SourceBuffer_ = std::make_unique<Buffer>(this->Context_, bytes, "visibility direction sources");
  }
  this->SourceBuffer_->Upload(this->Sources_.data(), bytes);
}

const Buffer& VisibilityGrid::DirectionSourceBuffer() const
{
  if (!this->SourceBuffer_)
  {
    throw InputError("the visibility grid has no directions yet");
  }
  return *this->SourceBuffer_;
}

void VisibilityGrid::RedirectDirections(const std::vector<std::pair<uint32_t, uint32_t>>& redirects)
{
  if (!this->Image_)
  {
    throw InputError("the visibility grid has no image to fill");
  }
  if (redirects.empty())
  {
    return;
  }
  const uint32_t count = uint32_t(this->Sources_.size());
  for (const auto& [to, from] : redirects)
  {
    if (to >= count || from >= count)
    {
      throw InputError("direction " + std::to_string(std::max(to, from)) + " is not one of the grid's " +
        std::to_string(count));
    }
  }
  for (const auto& [to, from] : redirects)
  {
    if (this->Sources_[from] != from)
    {
      throw InputError("direction " + std::to_string(to) + " cannot read direction " + std::to_string(from) +
        ", which itself reads another");
    }
  }
  for (const auto& [to, from] : redirects)
  {
    this->Sources_[to] = from;
  }
  this->UploadSources();
  this->ContentSerial_ = NewSerial();
}

// Rows of 16 bytes (volume_params.h): a member that breaks the rule changes the size.
static_assert(sizeof(shared::VsSweepParams) == sizeof(shared::VsVolumeParams) + sizeof(shared::VsGridParams) + 6 * 16,
  "VsSweepParams: rows of 16 bytes (volume_params.h)");

void VisibilityGrid::Compute(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const VolumeGeometry& geometry, const std::vector<glm::dvec4>& worldClipPlanes,
  const VisibilityGridParameters& parameters, const std::vector<uint32_t>& requested, const Progress& progress)
{
  const auto wallStart = std::chrono::steady_clock::now();
  parameters.Validate();
  if (worldClipPlanes.size() > shared::VS_MAX_CLIP_PLANES)
  {
    throw InputError("at most " + std::to_string(shared::VS_MAX_CLIP_PLANES) +
      " clipping planes that cut the volume are supported, got " + std::to_string(worldClipPlanes.size()));
  }
  const auto& info = this->Context_->Info();
  const uint64_t maxFloats = WorkBufferFloats(info);

  std::vector<uint32_t> directions = requested;
  // A new layout swept in part: the other directions read 0, never the fresh image's garbage.
  this->Allocate(geometry, parameters, !directions.empty());
  if (directions.empty())
  {
    for (uint32_t n = 0; n < parameters.DirectionResolution * parameters.DirectionResolution; ++n)
    {
      directions.push_back(n);
    }
  }
  this->Plan_ = SweepPlan::Make(geometry, parameters, maxFloats, directions, 8, info.MaxImageDimension3D);

  // What every dispatch shares.
  shared::VsSweepParams g{};
  g.volume = MakeVolumeParams(geometry, tf,
    parameters.NearestInterpolation ? shared::VS_INTERPOLATION_NEAREST : shared::VS_INTERPOLATION_LINEAR, worldClipPlanes,
    &majorants);
  g.grid.cellSize = this->Plan_.CellSize;
  g.grid.cells = glm::uvec3(this->Plan_.Cells[0], this->Plan_.Cells[1], this->Plan_.Cells[2]);
  g.grid.side = this->Plan_.Side;
  auto dims = volume.Dims();
  auto bricks = majorants.Bricks();
  const double step = parameters.StepSize > 0.0 ? parameters.StepSize : geometry.MinSpacing;
  g.step = float(step);
  g.stopVisibility = parameters.StopTransmittance;
  g.supersamples = parameters.BruteForceSamples;
  g.seed = 1u;
  // The occupied box: the bricks of nonzero majorant (each covers voxels [b B, (b + 1) B]),
  // widened by a pooled texel's reach (P voxels, and one for nearest-neighbour cells and rounding).
  {
    const auto& m = majorants.Majorants();
    const uint32_t B = majorants.BrickSize();
    glm::ivec3 lo(std::numeric_limits<int>::max()), hi(std::numeric_limits<int>::min());
    size_t i = 0;
    for (uint32_t z = 0; z < bricks[2]; ++z)
      for (uint32_t y = 0; y < bricks[1]; ++y)
        for (uint32_t x = 0; x < bricks[0]; ++x, ++i)
        {
          if (i < m.size() && !(m[i] == 0.0f))
          {
            lo = glm::min(lo, glm::ivec3(int(x), int(y), int(z)));
            hi = glm::max(hi, glm::ivec3(int(x), int(y), int(z)));
          }
        }
    if (m.size() != size_t(bricks[0]) * bricks[1] * bricks[2])
    {
      // Not the layout expected: no skipping.
      g.occupiedMin = g.volume.boxMin;
      g.occupiedMax = g.volume.boxMax;
    }
    else if (lo.x > hi.x)
    {
      // Nothing occludes: a degenerate box outside the volume, which no ray's interval overlaps.
      g.occupiedMin = g.occupiedMax = geometry.BoxMin - 8.0f;
    }
    else
    {
      const float margin = float(parameters.Algorithm == VisibilityGridParameters::Method::Sweep
                                     ? parameters.PoolingFactor()
                                     : 1u) +
        1.0f;
      const glm::vec3 a = glm::vec3(lo) * float(B) - margin;
      const glm::vec3 b = glm::vec3(hi + 1) * float(B) + margin;
      g.occupiedMin = glm::max(a, geometry.BoxMin);
      g.occupiedMax = glm::min(b, geometry.BoxMax);
    }
  }
  const uint32_t factor = parameters.Algorithm == VisibilityGridParameters::Method::Sweep ? parameters.PoolingFactor() : 1u;
  if (factor > 1)
  {
    const uint32_t brick = PooledExtinction::BrickTexels(factor);
    glm::uvec3 pooled, poolBricks;
    for (int i = 0; i < 3; ++i)
    {
      pooled[i] = (dims[i] + factor - 1) / factor;
      poolBricks[i] = (pooled[i] + brick - 1) / brick;
    }
    g.poolVoxels = float(factor);
    g.poolBrickSize = float(brick);
    g.poolCentre = 0.5f * float(factor - 1);
    g.poolStep = float(step * factor);
    g.poolDims = pooled;
    g.poolBricks = poolBricks;
  }
  Buffer globals(this->Context_, sizeof(g), "sweep parameters");
  globals.Upload(&g, sizeof(g));

  this->LastSeconds_ = 0.0;
  this->LastDispatches_ = 0;
  this->LastStageSeconds_.clear();
  this->LastStageCpuSeconds_.clear();
  if (parameters.Algorithm == VisibilityGridParameters::Method::Sweep)
  {
    this->RunSweeps(volume, tf, majorants, globals, progress);
  }
  else
  {
    this->RunBruteForce(volume, tf, majorants, globals, directions, progress);
  }
  this->DirectionsComputed_ += directions.size();
  // Computed directions read their own values again.
  bool redirected = false;
  for (uint32_t n : directions)
  {
    redirected |= this->Sources_[n] != n;
    this->Sources_[n] = n;
  }
  if (redirected)
  {
    this->UploadSources();
  }
  this->ContentSerial_ = NewSerial();
  this->LastWallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
}

void VisibilityGrid::RunBruteForce(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, Buffer& globals, const std::vector<uint32_t>& directions, const Progress& progress)
{
  const uint32_t extinctionFactor = volume.Factor() ? 1u : 0u;
  if (!this->Brute_ || this->BruteFactor_ != extinctionFactor)
  {
    using B = BindingType;
    this->Brute_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_visibility_bruteforce),
      BindingTypes(shared::VS_BRUTE_BINDING_COUNT,
        { { shared::VS_BRUTE_VOLUME, B::StorageImage }, { shared::VS_BRUTE_TF, B::UniformTexelBuffer },
          { shared::VS_BRUTE_MAJORANT, B::StorageImage }, { shared::VS_BRUTE_GLOBALS, B::StorageBuffer },
          { shared::VS_BRUTE_VISIBILITY, B::StorageImage }, { shared::VS_BRUTE_FACTOR_IMAGE, B::StorageImage } }),
      sizeof(SlicePush), extinctionFactor ? "visibility brute force (gradient opacity)" : "visibility brute force",
      { 0u, extinctionFactor });
    this->BruteFactor_ = extinctionFactor;
  }
  DescriptorSet set(*this->Brute_);
  set.Bind(shared::VS_BRUTE_VOLUME, volume.Image())
    .BindTexels(shared::VS_BRUTE_TF, tf.Lut(), vk::Format::eR32Sfloat)
    .Bind(shared::VS_BRUTE_MAJORANT, majorants.Image())
    .Bind(shared::VS_BRUTE_GLOBALS, globals)
    .Bind(shared::VS_BRUTE_VISIBILITY, *this->Image_);
  set.Bind(shared::VS_BRUTE_FACTOR_IMAGE, volume.Factor() ? *volume.Factor() : volume.Image()); // unread without a factor
  const auto& c = this->Plan_.Cells;
  const uint32_t cells = c[0] * c[1] * c[2];
  const uint32_t maxGroups = this->Context_->Info().MaxComputeWorkGroupCount[0];
  size_t done = 0;
  for (uint32_t n : directions)
  {
    Batch cmd(this->Context_);
    cmd.BeginTimer("bruteforce");
    for (uint32_t first = 0; first < cells; first += maxGroups * 64)
    {
      SlicePush push{ first, n };
      uint32_t groups = std::min(maxGroups, (cells - first + 63) / 64);
      cmd.Dispatch(*this->Brute_, set, &push, sizeof(push), groups, 1, 1);
    }
    cmd.EndTimer();
    cmd.Submit();
    this->LastSeconds_ += cmd.Seconds("bruteforce");
    this->LastDispatches_ += cmd.DispatchCount();
    ++done;
    if (progress)
    {
      progress(double(done) / double(directions.size()));
    }
  }
}

std::vector<float> VisibilityGrid::Download() const
{
  if (!this->Image_)
  {
    return {};
  }
  const auto& c = this->Plan_.Cells;
  const uint32_t d = this->Plan_.Side;
  const uint64_t texels = uint64_t(c[0]) * d * c[1] * d * c[2];
  std::vector<float> raw(texels);
  const uint32_t bytes = Image3D::TexelBytes(this->Image_->Format());
  std::vector<uint8_t> data(texels * bytes);
  this->Image_->Download(data.data(), data.size());
  for (uint64_t i = 0; i < texels; ++i)
  {
    if (bytes == 1)
    {
      raw[i] = data[i] / 255.0f;
    }
    else if (bytes == 2)
    {
      uint16_t v;
      std::memcpy(&v, &data[2 * i], 2);
      raw[i] = v / 65535.0f;
    }
    else
    {
      std::memcpy(&raw[i], &data[4 * i], 4);
    }
  }
  // Image (x * D + u, y * D + v, z) -> cell-major, direction-minor; a redirected direction reads
  // its source's values.
  std::vector<float> out(texels);
  const uint64_t w = uint64_t(c[0]) * d, h = uint64_t(c[1]) * d;
  for (uint32_t z = 0; z < c[2]; ++z)
    for (uint32_t y = 0; y < c[1]; ++y)
      for (uint32_t x = 0; x < c[0]; ++x)
        for (uint32_t n = 0; n < d * d; ++n)
        {
          const uint32_t m = this->Sources_[n];
          uint64_t tx = uint64_t(x) * d + m % d, ty = uint64_t(y) * d + m / d;
          out[((uint64_t(z) * c[1] + y) * c[0] + x) * d * d + n] = raw[(z * h + ty) * w + tx];
        }
  return out;
}
}
