#include "vsMajorantGrid.h"
#include "sampling/bindings.h"
#include "sampling/majorant_params.h"
#include "vsBatch.h"
#include "vsBrickRanges.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsEmptySpaceDistance.h"
#include "vsExtinctionRangeQuery.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsParallelSlabs.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_majorant_minmax.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vs
{
MajorantGrid::MajorantGrid(std::shared_ptr<Context> context, uint32_t brickSize)
  : Context_(std::move(context))
  , BrickSize_(brickSize)
{
  if (brickSize < 1)
  {
    throw InputError("the majorant brick size must be at least 1 voxel");
  }
}

MajorantGrid::~MajorantGrid() = default;

namespace
{
// Per brick b of B voxels along each axis: min, max and a non-finite flag over voxels [bB, (b+1)B]
// (vsBrickRanges.h), the slices in slabs on the host's threads (vsParallelSlabs.h).
std::vector<float> HostRanges(const float* v, std::array<uint32_t, 3> dims, uint32_t B)
{
  BrickRanges ranges(dims, B);
  const uint64_t slice = uint64_t(dims[0]) * dims[1];
  ForSlabs(dims[2], [&](unsigned, uint64_t z0, uint64_t z1) {
    for (uint64_t z = z0; z < z1; ++z)
    {
      ranges.AddSlice(uint32_t(z), v + z * slice);
    }
  });
  return ranges.Finish();
}
}

void MajorantGrid::UpdateRanges(const DeviceVolume& volume, const float* hostScalars)
{
  auto dims = volume.Dims();
  const std::array<uint32_t, 3> bricks = BrickRanges::Bricks(dims, this->BrickSize_);
  const uint64_t count = uint64_t(bricks[0]) * bricks[1] * bricks[2];
  if (hostScalars)
  {
    const auto start = std::chrono::steady_clock::now();
    this->Ranges_ = HostRanges(hostScalars, dims, this->BrickSize_);
    this->LastSeconds_ = 0.0; // no device time
    this->LastHostSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  else
  {
    auto shared = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_majorant_minmax),
      BindingTypes(shared::VS_RANGES_BINDING_COUNT,
        { { shared::VS_RANGES_VOLUME, BindingType::StorageImage }, { shared::VS_RANGES_OUTPUT, BindingType::StorageBuffer } }),
      sizeof(shared::VsMajorantPush), "majorant ranges");
    const ComputePipeline& pipeline = *shared;
    Buffer ranges(this->Context_, count * 4 * sizeof(float), "brick ranges");
    DescriptorSet set(pipeline);
    set.Bind(shared::VS_RANGES_VOLUME, volume.Image()).Bind(shared::VS_RANGES_OUTPUT, ranges);
    shared::VsMajorantPush push{};
    push.bricks = glm::uvec3(bricks[0], bricks[1], bricks[2]);
    push.brickSize = this->BrickSize_;
    push.dims = glm::ivec3(int32_t(dims[0]), int32_t(dims[1]), int32_t(dims[2]));
    Batch batch(this->Context_);
    batch.BeginTimer("ranges");
    batch.Dispatch(pipeline, set, &push, sizeof(push), (bricks[0] + 3) / 4, (bricks[1] + 3) / 4, (bricks[2] + 3) / 4);
    batch.EndTimer();
    batch.Submit();
    this->LastSeconds_ = batch.Seconds("ranges");
    this->LastHostSeconds_ = 0.0;
    this->Ranges_.resize(count * 4);
    ranges.Download(this->Ranges_.data(), count * 4 * sizeof(float));
  }
  this->Dims_ = dims;
  this->SetRanges(bricks);
}

void MajorantGrid::UpdateRanges(const DeviceVolume& volume, const BrickRanges& ranges)
{
  if (ranges.Dims() != volume.Dims() || ranges.BrickSize() != this->BrickSize_)
  {
    throw InputError("the brick ranges were made for another volume or brick size");
  }
  const auto start = std::chrono::steady_clock::now();
  this->Ranges_ = ranges.Finish();
  this->LastSeconds_ = 0.0; // no device time
  this->LastHostSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->Dims_ = volume.Dims();
  this->SetRanges(BrickRanges::Bricks(volume.Dims(), this->BrickSize_));
}

void MajorantGrid::SetRanges(std::array<uint32_t, 3> bricks)
{
  if (bricks != this->Bricks_ || !this->Image_)
  {
    this->Image_.reset();
    this->TrackingImage_.reset();
    this->Image_ = std::make_unique<Image3D>(this->Context_, bricks[0], bricks[1], bricks[2],
      vk::Format::eR32Sfloat, "majorant grid");
    this->TrackingImage_ = std::make_unique<Image3D>(this->Context_, bricks[0], bricks[1], bricks[2],
      vk::Format::eR32G32B32A32Sfloat, "majorant walk bricks");
    this->Bricks_ = bricks;
  }
  this->Majorants_.clear();
  this->FactorRanges_.clear();
  ++this->RangeUpdates_;
}

void MajorantGrid::SetFactor(const float* factor)
{
  this->FactorRanges_.clear();
  if (!factor)
  {
    return;
  }
  if (!this->Image_)
  {
    throw InputError("the majorants' factor needs the brick ranges first (UpdateRanges)");
  }
  // The factor's range per brick over the scalars' footprint (the factor is finite everywhere).
  const std::vector<float> r = HostRanges(factor, this->Dims_, this->BrickSize_);
  const size_t count = r.size() / 4;
  this->FactorRanges_.assign(2 * count, 0.0f);
  for (size_t b = 0; b < count; ++b)
  {
    const float lo = std::min(r[4 * b], r[4 * b + 1]), hi = std::max(r[4 * b], r[4 * b + 1]);
    // A trilinear interpolant of the factor may round a few ulps past its corners (three mixes
    // of float): widen by 1e-6 of the value, which keeps 0 at 0 (empty bricks stay empty).
    this->FactorRanges_[2 * b] = std::max(0.0f, lo * (1.0f - 1e-6f));
    this->FactorRanges_[2 * b + 1] = hi * (1.0f + 1e-6f);
  }
}

void MajorantGrid::UpdateMajorants(const TransferFunctionSamples& tf)
{
  if (!this->Image_)
  {
    throw InputError("majorants need the brick ranges first (UpdateRanges)");
  }
  const size_t count = this->Ranges_.size() / 4;
  this->Majorants_.assign(count, 0.0f);
  this->Controls_.assign(count, 0.0f);
  const ExtinctionRangeQuery extinction(tf);
  for (size_t i = 0; i < count; ++i)
  {
    float lo = this->Ranges_[4 * i], hi = this->Ranges_[4 * i + 1];
    const bool gap = this->Ranges_[4 * i + 2] != 0.0f; // a non-finite voxel: empty samples
    if (lo <= hi)
    {
      this->Majorants_[i] = extinction.Max(lo, hi);
      this->Controls_[i] = gap ? 0.0f : std::min(extinction.Min(lo, hi), this->Majorants_[i]);
      if (!this->FactorRanges_.empty())
      {
        // Float products round monotonically: sigma <= max sigma and g <= max g give
        // fl(sigma g) <= fl(max sigma max g), and the same below for the control.
        this->Majorants_[i] *= this->FactorRanges_[2 * i + 1];
        this->Controls_[i] = std::min(this->Controls_[i] * this->FactorRanges_[2 * i], this->Majorants_[i]);
      }
    }
  }
  this->Image_->Upload(this->Majorants_.data(), count * sizeof(float));
  this->EmptyDistances_ = EmptySpaceDistance(this->Majorants_, this->Bricks_, kMaxEmptyDistance);
  std::vector<float> tracking(4 * count, 0.0f);
  for (size_t i = 0; i < count; ++i)
  {
    tracking[4 * i] = this->Majorants_[i];
    tracking[4 * i + 1] = this->Controls_[i];
    tracking[4 * i + 2] = this->EmptyDistances_[i];
  }
  this->TrackingImage_->Upload(tracking.data(), tracking.size() * sizeof(float));
  ++this->MajorantUpdates_;
}

double MajorantGrid::EmptyFraction() const
{
  if (this->Majorants_.empty())
  {
    return 0.0;
  }
  size_t empty = std::count(this->Majorants_.begin(), this->Majorants_.end(), 0.0f);
  return double(empty) / double(this->Majorants_.size());
}

float MajorantGrid::MaxMajorant() const
{
  return this->Majorants_.empty() ? 0.0f : *std::max_element(this->Majorants_.begin(), this->Majorants_.end());
}
}
