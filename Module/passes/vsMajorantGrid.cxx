#include "vsMajorantGrid.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsEmptySpaceDistance.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_majorant_minmax.h"

#include <algorithm>

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

void MajorantGrid::UpdateRanges(const DeviceVolume& volume)
{
  auto dims = volume.Dims();
  std::array<uint32_t, 3> bricks;
  for (int i = 0; i < 3; ++i)
  {
    // A brick covers voxels [bB, (b+1)B]; the last voxel index is dims-1.
    bricks[i] = std::max<uint32_t>(1, (dims[i] - 1 + this->BrickSize_ - 1) / this->BrickSize_);
  }
  const uint64_t count = uint64_t(bricks[0]) * bricks[1] * bricks[2];
  auto shared = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_majorant_minmax),
    { BindingType::StorageImage, BindingType::StorageBuffer }, 32, "majorant ranges");
  const ComputePipeline& pipeline = *shared;
  Buffer ranges(this->Context_, count * 4 * sizeof(float), "brick ranges");
  DescriptorSet set(pipeline);
  set.Bind(0, volume.Image()).Bind(1, ranges);
  struct
  {
    uint32_t bricks[4];
    int32_t dims[4];
  } push = { { bricks[0], bricks[1], bricks[2], this->BrickSize_ },
    { int32_t(dims[0]), int32_t(dims[1]), int32_t(dims[2]), 0 } };
  Batch batch(this->Context_);
  batch.BeginTimer("ranges");
  batch.Dispatch(pipeline, set, &push, sizeof(push), (bricks[0] + 3) / 4, (bricks[1] + 3) / 4, (bricks[2] + 3) / 4);
  batch.EndTimer();
  batch.Submit();
  this->LastSeconds_ = batch.Seconds("ranges");
  this->Ranges_.resize(count * 4);
  ranges.Download(this->Ranges_.data(), count * 4 * sizeof(float));
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
  this->Dims_ = dims;
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
  const auto& d = this->Dims_;
  const auto& n = this->Bricks_;
  const uint32_t B = this->BrickSize_;
  this->FactorRanges_.assign(size_t(2) * n[0] * n[1] * n[2], 0.0f);
  for (uint32_t bz = 0; bz < n[2]; ++bz)
  {
    for (uint32_t by = 0; by < n[1]; ++by)
    {
      for (uint32_t bx = 0; bx < n[0]; ++bx)
      {
        // Voxels [bB, (b+1)B] clamped to the volume, as majorant_minmax.comp reads the scalars.
        float lo = 3.4e38f, hi = 0.0f;
        for (uint32_t z = bz * B; z <= std::min(bz * B + B, d[2] - 1); ++z)
        {
          for (uint32_t y = by * B; y <= std::min(by * B + B, d[1] - 1); ++y)
          {
            const float* row = factor + (uint64_t(z) * d[1] + y) * d[0];
            for (uint32_t x = bx * B; x <= std::min(bx * B + B, d[0] - 1); ++x)
            {
              lo = std::min(lo, row[x]);
              hi = std::max(hi, row[x]);
            }
          }
        }
        const size_t b = (size_t(bz) * n[1] + by) * n[0] + bx;
        // A trilinear interpolant of the factor may round a few ulps past its corners (three mixes
        // of float): widen by 1e-6 of the value, which keeps 0 at 0 (empty bricks stay empty).
        this->FactorRanges_[2 * b] = std::max(0.0f, lo * (1.0f - 1e-6f));
        this->FactorRanges_[2 * b + 1] = hi * (1.0f + 1e-6f);
      }
    }
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
  for (size_t i = 0; i < count; ++i)
  {
    float lo = this->Ranges_[4 * i], hi = this->Ranges_[4 * i + 1];
    const bool gap = this->Ranges_[4 * i + 2] != 0.0f; // a non-finite voxel: empty samples
    if (lo <= hi)
    {
      this->Majorants_[i] = tf.MaxExtinction(lo, hi);
      this->Controls_[i] = gap ? 0.0f : std::min(tf.MinExtinction(lo, hi), this->Majorants_[i]);
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
