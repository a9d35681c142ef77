#include "vsPooledExtinction.h"
#include "sampling/bindings.h"
#include "sampling/pool_params.h"
#include "vsBatch.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_sweep_pool.h"
#include "vs_spirv_sweep_pool_occupancy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <functional>
#include <string>
#include <string_view>

namespace vs
{
namespace
{
template <typename T>
size_t HashOf(const std::vector<T>& v)
{
  return std::hash<std::string_view>()(
    std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T)));
}
}

PooledExtinction::PooledExtinction(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

PooledExtinction::~PooledExtinction() = default;

uint32_t PooledExtinction::BrickTexels(uint32_t factor)
{
  return std::max<uint32_t>(1, 8 / std::max<uint32_t>(factor, 1));
}

bool PooledExtinction::Key::operator==(const Key& o) const
{
  const Settings& a = this->Pooling;
  const Settings& b = o.Pooling;
  return this->Volume == o.Volume && this->TF == o.TF && this->Majorants == o.Majorants &&
    this->RangeUpdates == o.RangeUpdates && this->MajorantUpdates == o.MajorantUpdates && this->TFHash == o.TFHash &&
    this->MajorantHash == o.MajorantHash && this->Dims == o.Dims && this->Range == o.Range &&
    this->NonFinite == o.NonFinite && this->ExtinctionFactor == o.ExtinctionFactor && a.Factor == b.Factor &&
    a.Max == b.Max && a.CropFlags == b.CropFlags && a.CropLo == b.CropLo && a.CropHi == b.CropHi;
}

PooledExtinction::Key PooledExtinction::MakeKey(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const Settings& settings)
{
  Key key;
  key.Volume = &volume;
  key.TF = &tf;
  key.Majorants = &majorants;
  key.RangeUpdates = majorants.RangeUpdates();
  key.MajorantUpdates = majorants.MajorantUpdates();
  key.TFHash = HashOf(tf.Samples().Entries) ^ (std::hash<float>()(tf.Samples().ScalarMin) * 31u) ^
    (std::hash<float>()(tf.Samples().ScalarMax) * 131u);
  key.MajorantHash = HashOf(majorants.Majorants());
  key.Dims = volume.Dims();
  key.Range = volume.Range();
  key.NonFinite = volume.NonFiniteCount();
  key.ExtinctionFactor = volume.Factor() ? volume.FactorSerial() : 0;
  key.Pooling = settings;
  if (!settings.CropFlags)
  {
    key.Pooling.CropLo = key.Pooling.CropHi = glm::vec3(0.0f);
  }
  return key;
}

bool PooledExtinction::IsCurrent(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const Settings& settings) const
{
  return this->Complete_ && this->Key_ == MakeKey(volume, tf, majorants, settings);
}

void PooledExtinction::Start(const Key& key, const DeviceVolume& volume)
{
  const uint32_t factor = key.Pooling.Factor;
  {
    // Specialised for the factor, the kind of pooling and whether cropping masks voxels.
    using B = BindingType;
    const uint32_t cropped = key.Pooling.CropFlags ? 1u : 0u;
    const uint32_t scaled = key.ExtinctionFactor ? 1u : 0u;
    this->FromQuads_ = this->VolumeQuads_ && volume.Quads();
    const uint32_t quads = this->FromQuads_ ? 1u : 0u;
    this->Pool_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_pool),
      BindingTypes(shared::VS_POOL_BINDING_COUNT,
        { { shared::VS_POOL_VOLUME, B::StorageImage }, { shared::VS_POOL_TF, B::UniformTexelBuffer },
          { shared::VS_POOL_POOLED, B::StorageImage }, { shared::VS_POOL_FACTOR_IMAGE, B::StorageImage },
          { shared::VS_POOL_QUADS, B::StorageImage } }),
      sizeof(shared::VsPoolPush),
      "sweep pool (P " + std::to_string(factor) + (key.Pooling.Max ? ", max" : ", mean") +
        (cropped ? ", cropped" : "") + (scaled ? ", gradient opacity" : "") + (quads ? ", 8-bit quads)" : ")"),
      { factor, key.Pooling.Max ? 1u : 0u, cropped, scaled, quads });
    this->OccupancyPipeline_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_pool_occupancy),
      BindingTypes(shared::VS_OCCUPANCY_BINDING_COUNT,
        { { shared::VS_OCCUPANCY_POOLED, B::StorageImage }, { shared::VS_OCCUPANCY_OUTPUT, B::StorageImage } }),
      sizeof(shared::VsOccupancyPush), "sweep pool occupancy");
  }
  const uint32_t brick = BrickTexels(factor);
  for (int i = 0; i < 3; ++i)
  {
    this->PooledDims_[i] = int((key.Dims[i] + factor - 1) / factor);
    this->Bricks_[i] = (this->PooledDims_[i] + int(brick) - 1) / int(brick);
  }
  this->Pooled_.reset();
  this->Occupancy_.reset();
  this->Pooled_ = std::make_unique<Image3D>(this->Context_, uint32_t(this->PooledDims_.x),
    uint32_t(this->PooledDims_.y), uint32_t(this->PooledDims_.z), vk::Format::eR32Sfloat, "pooled extinction");
  this->Occupancy_ = std::make_unique<Image3D>(this->Context_, uint32_t(this->Bricks_.x), uint32_t(this->Bricks_.y),
    uint32_t(this->Bricks_.z), vk::Format::eR32Sfloat, "pooled extinction occupancy");
  this->Key_ = key;
  this->Started_ = true;
  this->Complete_ = false;
  this->NextSlice_ = 0;
}

double PooledExtinction::PoolSlices(
  const DeviceVolume& volume, const TransferFunctionTable& tf, uint32_t z0, uint32_t z1)
{
  // An integer-coded volume is pooled from its quads (its float image is then never asked for); the
  // binding not read gets a placeholder texel.
  const Image3D* quads = this->FromQuads_ ? volume.Quads() : nullptr;
  if (!this->NoImage_)
  {
    this->NoImage_ = std::make_unique<Image3D>(this->Context_, 1, 1, 1, vk::Format::eR32Sfloat, "no float volume");
    this->NoQuads_ = std::make_unique<Image3D>(this->Context_, 1, 1, 1, vk::Format::eR32Uint, "no volume quads");
  }
  const Image3D& floats = quads ? *this->NoImage_ : volume.Image();
  DescriptorSet set(*this->Pool_);
  set.Bind(shared::VS_POOL_VOLUME, floats)
    .BindTexels(shared::VS_POOL_TF, tf.Lut(), vk::Format::eR32Sfloat)
    .Bind(shared::VS_POOL_POOLED, *this->Pooled_)
    .Bind(shared::VS_POOL_QUADS, quads ? *quads : *this->NoQuads_);
  set.Bind(shared::VS_POOL_FACTOR_IMAGE, volume.Factor() ? *volume.Factor() : floats); // unread without a factor
  const Key& key = this->Key_;
  shared::VsPoolPush pp{};
  pp.dims = glm::ivec3(int(key.Dims[0]), int(key.Dims[1]), int(key.Dims[2]));
  pp.firstSlice = z0;
  pp.pooled = this->PooledDims_;
  pp.cropLo = key.Pooling.CropLo;
  pp.cropHi = key.Pooling.CropHi;
  pp.cropFlags = key.Pooling.CropFlags;
  pp.quadZero = quads ? volume.QuadOffset() : 0.0f;
  pp.tf = tf.Params();
  Batch cmd(this->Context_);
  cmd.BeginTimer("pool");
  cmd.Dispatch(*this->Pool_, set, &pp, sizeof(pp), uint32_t(this->PooledDims_.x + 3) / 4,
    uint32_t(this->PooledDims_.y + 3) / 4, (z1 - z0 + SlabSlices - 1) / SlabSlices);
  cmd.Barrier();
  cmd.EndTimer();
  cmd.Submit();
  return std::max(cmd.Seconds("pool"), 1e-9);
}

double PooledExtinction::Finish()
{
  DescriptorSet set(*this->OccupancyPipeline_);
  set.Bind(shared::VS_OCCUPANCY_POOLED, *this->Pooled_).Bind(shared::VS_OCCUPANCY_OUTPUT, *this->Occupancy_);
  shared::VsOccupancyPush op{};
  op.pooled = this->PooledDims_;
  op.bricks = this->Bricks_;
  op.brickTexels = int(BrickTexels(this->Key_.Pooling.Factor));
  Batch cmd(this->Context_);
  cmd.BeginTimer("occupancy");
  cmd.Dispatch(*this->OccupancyPipeline_, set, &op, sizeof(op), uint32_t(this->Bricks_.x + 3) / 4,
    uint32_t(this->Bricks_.y + 3) / 4, uint32_t(this->Bricks_.z + 3) / 4);
  cmd.Barrier();
  cmd.EndTimer();
  cmd.Submit();
  this->Complete_ = true;
  ++this->Builds_;
  return std::max(cmd.Seconds("occupancy"), 1e-9);
}

double PooledExtinction::Ensure(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const Settings& settings)
{
  return this->Advance(volume, tf, majorants, settings, std::numeric_limits<double>::infinity());
}

double PooledExtinction::RemainingSeconds() const
{
  if (!this->Started_ || this->Complete_)
  {
    return 0.0;
  }
  const uint32_t slices = uint32_t(this->PooledDims_.z);
  return slices > this->NextSlice_ ? double(slices - this->NextSlice_) * this->SecondsPerSlice_ : 0.0;
}

double PooledExtinction::Advance(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const Settings& settings, double budgetSeconds)
{
  const Key key = MakeKey(volume, tf, majorants, settings);
  if (!this->Started_ || !(key == this->Key_))
  {
    this->Start(key, volume);
  }
  if (this->Complete_)
  {
    return 0.0;
  }
  const uint32_t slices = uint32_t(this->PooledDims_.z);
  double spent = 0.0;
  if (this->NextSlice_ < slices)
  {
    // Slabs while their estimated time fits the budget; everything when unbounded. The first slab
    // is built whatever the budget (its cost is unknown until then); after it, a budget smaller
    // than a slab builds nothing and the caller's allowance grows until one fits. (At least a slab
    // per call made Auto's 5% share 11% of the first second on the 0.5 mm MRI at 256^2: a slab of
    // 10-20 ms after every 55 ms frame.)
    uint32_t count = slices - this->NextSlice_;
    if (std::isfinite(budgetSeconds))
    {
      const double per = this->SecondsPerSlice_;
      const uint32_t fit = per > 0.0 ? uint32_t(std::min<double>(std::max(0.0, budgetSeconds) / per, slices)) : SlabSlices;
      count = std::min(fit / SlabSlices * SlabSlices, slices - this->NextSlice_);
      if (count == 0)
      {
        return 0.0;
      }
    }
    const uint32_t z0 = this->NextSlice_, z1 = z0 + count;
    const double seconds = this->PoolSlices(volume, tf, z0, z1);
    const double per = seconds / double(count);
    this->SecondsPerSlice_ = this->SecondsPerSlice_ > 0.0 ? 0.5 * (this->SecondsPerSlice_ + per) : per;
    this->NextSlice_ = z1;
    spent += seconds;
  }
  if (this->NextSlice_ >= slices)
  {
    spent += this->Finish();
  }
  return spent;
}
}
