#include "vsMajorantGrid.h"
#include "sampling/bindings.h"
#include "sampling/majorant_params.h"
#include "vsBatch.h"
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
// (inclusive, clamped to the volume), as majorant_minmax.comp computes them, by three separable
// passes (x, then y, then z), each reading its input once.
struct Span
{
  float Min = 3.4e38f, Max = -3.4e38f;
  bool Gap = false;
  void Add(const Span& o)
  {
    Min = std::min(Min, o.Min);
    Max = std::max(Max, o.Max);
    Gap = Gap || o.Gap;
  }
};

std::vector<float> HostRanges(const float* v, std::array<uint32_t, 3> dims, std::array<uint32_t, 3> bricks, uint32_t B)
{
  const size_t nx = dims[0], ny = dims[1], nz = dims[2];
  const size_t bx = bricks[0], by = bricks[1], bz = bricks[2];
  auto lo = [&](size_t b) { return b * B; };
  auto hi = [&](size_t b, size_t n) { return std::min<size_t>(b * B + B, n - 1); };
  // Each pass in slabs on the host's threads (vsParallelSlabs.h): every output element is made by one
  // slab from inputs the passes before finished, so the result does not depend on the split.
  std::vector<Span> rows(bx * ny * nz); // (brick x, y, z)
  ForSlabs(nz, [&](unsigned, uint64_t z0, uint64_t z1) {
    for (size_t z = z0; z < z1; ++z)
    {
      for (size_t y = 0; y < ny; ++y)
      {
        const float* row = v + (z * ny + y) * nx;
        for (size_t b = 0; b < bx; ++b)
        {
          Span s;
          for (size_t x = lo(b); x <= hi(b, nx); ++x)
          {
            const float f = row[x];
            if (!std::isfinite(f)) // stored as NaN on the device: empty space
            {
              s.Gap = true;
            }
            else
            {
              s.Min = std::min(s.Min, f);
              s.Max = std::max(s.Max, f);
            }
          }
          rows[(z * ny + y) * bx + b] = s;
        }
      }
    }
  });
  std::vector<Span> planes(bx * by * nz); // (brick x, brick y, z)
  ForSlabs(nz, [&](unsigned, uint64_t z0, uint64_t z1) {
    for (size_t z = z0; z < z1; ++z)
    {
      for (size_t b = 0; b < by; ++b)
      {
        for (size_t y = lo(b); y <= hi(b, ny); ++y)
        {
          for (size_t x = 0; x < bx; ++x)
          {
            planes[(z * by + b) * bx + x].Add(rows[(z * ny + y) * bx + x]);
          }
        }
      }
    }
  });
  std::vector<float> ranges(4 * bx * by * bz);
  ForSlabs(bz, [&](unsigned, uint64_t b0, uint64_t b1) {
    for (size_t b = b0; b < b1; ++b)
    {
      for (size_t y = 0; y < by; ++y)
      {
        for (size_t x = 0; x < bx; ++x)
        {
          Span s;
          for (size_t z = lo(b); z <= hi(b, nz); ++z)
          {
            s.Add(planes[(z * by + y) * bx + x]);
          }
          float* r = &ranges[4 * ((b * by + y) * bx + x)];
          const bool any = s.Min <= s.Max;
          r[0] = any ? s.Min : 1.0f;
          r[1] = any ? s.Max : 0.0f;
          r[2] = s.Gap ? 1.0f : 0.0f;
          r[3] = 0.0f;
        }
      }
    }
  });
  return ranges;
}
}

void MajorantGrid::UpdateRanges(const DeviceVolume& volume, const float* hostScalars)
{
  auto dims = volume.Dims();
  std::array<uint32_t, 3> bricks;
  for (int i = 0; i < 3; ++i)
  {
    // A brick covers voxels [bB, (b+1)B]; the last voxel index is dims-1.
    bricks[i] = std::max<uint32_t>(1, (dims[i] - 1 + this->BrickSize_ - 1) / this->BrickSize_);
  }
  const uint64_t count = uint64_t(bricks[0]) * bricks[1] * bricks[2];
  if (hostScalars)
  {
    const auto start = std::chrono::steady_clock::now();
    this->Ranges_ = HostRanges(hostScalars, dims, bricks, this->BrickSize_);
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
  // The factor's range per brick over the scalars' footprint (the factor is finite everywhere).
  const std::vector<float> r = HostRanges(factor, this->Dims_, this->Bricks_, this->BrickSize_);
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
