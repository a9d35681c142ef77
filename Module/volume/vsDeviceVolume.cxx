#include "vsDeviceVolume.h"
#include "sampling/bindings.h"
#include "sampling/quads_params.h"
#include "vsBatch.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsParallelSlabs.h"
#include "vsSerial.h"
#include "vsPipeline.h"
#include "vsStagedUpload.h"

#include "vs_spirv_volume_from_quads.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace vs
{
void DeviceVolume::CheckFits(Context& context, std::array<uint32_t, 3> dims)
{
  Image3D::CheckLimits(context, dims[0], dims[1], dims[2], vk::Format::eR32Sfloat, "volume");
}

namespace
{
// Staging per chunk of slices, for all images together: small enough to stay in the cache while the
// host fills it and the queue copies it.
constexpr uint64_t kChunkBytes = 1ull << 20;

// Slice z's quads (see the header) from its floats: codes (value - offset), then each texel packs
// its footprint's 4 codes of the slice (neighbours clamped).
void PackQuads(const float* src, float offset, std::array<uint32_t, 3> dims, uint8_t* codes, uint32_t* quads)
{
  const uint64_t slice = uint64_t(dims[0]) * dims[1];
  for (uint64_t i = 0; i < slice; ++i)
  {
    codes[i] = uint8_t(src[i] - offset);
  }
  for (uint32_t y = 0; y < dims[1]; ++y)
  {
    const uint8_t* row = codes + uint64_t(y) * dims[0];
    const uint8_t* next = codes + uint64_t(std::min(y + 1, dims[1] - 1)) * dims[0];
    uint32_t* out = quads + uint64_t(y) * dims[0];
    const uint32_t last = dims[0] - 1;
    for (uint32_t x = 0; x < last; ++x)
    {
      out[x] = uint32_t(row[x]) | uint32_t(row[x + 1]) << 8 | uint32_t(next[x]) << 16 | uint32_t(next[x + 1]) << 24;
    }
    // The last column's right neighbour is itself (clamped).
    out[last] =
      uint32_t(row[last]) | uint32_t(row[last]) << 8 | uint32_t(next[last]) << 16 | uint32_t(next[last]) << 24;
  }
}
}

DeviceVolume::DeviceVolume(std::shared_ptr<Context> context, const HostScalars& scalars,
  std::array<uint32_t, 3> dims, const SliceVisitor& eachSlice)
  : Context_(context)
  , Dims_(dims)
{
  CheckFits(*context, dims);
  if (!scalars.Data)
  {
    throw InputError("the device volume was given no scalars");
  }
  const uint64_t slice = uint64_t(dims[0]) * dims[1];
  // First the range, the integer test and the count (in slabs of slices on the host's threads,
  // vsParallelSlabs.h; combined over the slabs): the quads' offset is the smallest value. On the
  // native integers this reads 1-2 bytes a voxel.
  std::vector<HostScalars::Summary> parts(SlabCount(dims[2]));
  ForSlabs(dims[2], [&](unsigned p, uint64_t z0, uint64_t z1) { parts[p] = scalars.Summarize(z0 * slice, z1 * slice); });
  float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
  bool integral = true;
  for (const auto& part : parts)
  {
    lo = std::min(lo, part.Lo);
    hi = std::max(hi, part.Hi);
    integral = integral && part.Integral;
    this->NonFinite_ += part.NonFinite;
  }
  if (lo <= hi)
  {
    this->Range_ = { { lo, hi } };
  }
  // Integer-coded: finite integers spanning at most 255 (quads of 8-bit codes, see the header).
  const bool coded = this->NonFinite_ == 0 && lo <= hi && integral && hi - lo <= 255.0f &&
    std::abs(lo) < 16777216.0f && std::abs(hi) < 16777216.0f && slice * dims[2] * 4 <= kMaxQuadBytes;
  if (coded)
  {
    try
    {
      Image3D::CheckLimits(*context, dims[0], dims[1], dims[2], vk::Format::eR32Uint, "volume quads");
      this->Quads_ =
        std::make_unique<Image3D>(context, dims[0], dims[1], dims[2], vk::Format::eR32Uint, "volume quads");
      this->QuadOffset_ = lo;
    }
    catch (const DeviceLimitError&)
    {
      // The quads only speed the kernel up: a volume that fits without them renders without them.
      this->Quads_.reset();
    }
  }
  // Then one pass per slice while it is in the cache: the quads or else the floats (non-finite as
  // NaN), and the caller's visit (the brick ranges), each slab staging and submitting its own chunks
  // of slices. With quads the float image waits for a pass that reads it (Image()).
  if (!this->Quads_)
  {
    this->Image_ = std::make_unique<Image3D>(context, dims[0], dims[1], dims[2], vk::Format::eR32Sfloat, "volume");
  }
  std::vector<Image3D*> images{ this->Quads_ ? this->Quads_.get() : this->Image_.get() };
  const uint32_t chunk = StagedUpload::SlicesPerChunk(images, kChunkBytes);
  const float offset = this->QuadOffset_;
  // On a CPU device the images are the host's memory, fresh: the copies would fault it in on the
  // driver's one queue thread (ch2better's 282 MB: 0.3-0.7 s on this VM). The slabs fault it in first,
  // in parallel (Image3D::PrefaultPages), all of it before any slab uploads: a slab's share of the bytes
  // is not its slices (the layout is the driver's), and a write that faults a page in over a neighbour's
  // slices already copied zeroed a voxel per page (VolumeQuads.EveryVoxelArrivesWhateverTheSlabsTiming).
  std::vector<Image3D::HostMemory> memory;
  for (Image3D* image : images)
  {
    memory.push_back(image->MapHostMemory());
  }
  const unsigned slabs = SlabCount(dims[2]);
  ForSlabs(dims[2], [&](unsigned p, uint64_t, uint64_t) {
    for (const Image3D::HostMemory& m : memory)
    {
      const uint64_t b0 = m.Bytes * p / slabs, b1 = m.Bytes * (p + 1) / slabs;
      if (m.Data)
      {
        Image3D::PrefaultPages(m.Data + b0, b1 - b0);
      }
    }
  });
  ForSlabs(dims[2], [&](unsigned, uint64_t z0, uint64_t z1) {
    StagedUpload upload(context, images, chunk);
    std::vector<float> floats(slice);
    const bool packed = this->Quads_ != nullptr;
    std::vector<uint8_t> codes(packed ? slice : 0);
    for (uint64_t z = z0; z < z1; z += chunk)
    {
      const uint32_t n = uint32_t(std::min<uint64_t>(chunk, z1 - z));
      upload.Begin(uint32_t(z), n);
      for (uint32_t k = 0; k < n; ++k)
      {
        // Converted into host memory (the staging may be write-combined), read from there.
        scalars.ToFloat((z + k) * slice, (z + k + 1) * slice, floats.data());
        if (packed)
        {
          PackQuads(floats.data(), offset, dims, codes.data(), static_cast<uint32_t*>(upload.Texels(0)) + k * slice);
        }
        else
        {
          std::memcpy(static_cast<float*>(upload.Texels(0)) + k * slice, floats.data(), slice * sizeof(float));
        }
        if (eachSlice)
        {
          eachSlice(uint32_t(z + k), floats.data());
        }
      }
      upload.Submit();
    }
    upload.Finish();
  });
  for (size_t i = 0; i < images.size(); ++i)
  {
    if (memory[i].Data)
    {
      images[i]->UnmapHostMemory();
    }
  }
}

DeviceVolume::~DeviceVolume() = default;

const Image3D& DeviceVolume::Image() const
{
  if (!this->Image_)
  {
    // Only an integer-coded volume comes without its float image: make it from the quads.
    const auto& d = this->Dims_;
    auto image = std::make_unique<Image3D>(this->Context_, d[0], d[1], d[2], vk::Format::eR32Sfloat, "volume");
    std::shared_ptr<ComputePipeline> pipeline = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_volume_from_quads),
      BindingTypes(shared::VS_QUADS_BINDING_COUNT,
        { { shared::VS_QUADS_INPUT, BindingType::StorageImage }, { shared::VS_QUADS_OUTPUT, BindingType::StorageImage } }),
      sizeof(shared::VsQuadsPush), "volume from quads");
    DescriptorSet set(*pipeline);
    set.Bind(shared::VS_QUADS_INPUT, *this->Quads_).Bind(shared::VS_QUADS_OUTPUT, *image);
    shared::VsQuadsPush push{};
    push.dims = glm::ivec3(int32_t(d[0]), int32_t(d[1]), int32_t(d[2]));
    push.quadZero = this->QuadOffset_;
    Batch batch(this->Context_);
    batch.Dispatch(*pipeline, set, &push, sizeof(push), (d[0] + 7) / 8, (d[1] + 7) / 8, d[2]);
    batch.Barrier();
    batch.Submit();
    this->Image_ = std::move(image);
  }
  return *this->Image_;
}

void DeviceVolume::SetFactor(const float* factor)
{
  this->Factor_.reset();
  if (factor)
  {
    this->Factor_ = std::make_unique<Image3D>(
      this->Context_, this->Dims_[0], this->Dims_[1], this->Dims_[2], vk::Format::eR32Sfloat, "extinction factor");
    const uint64_t slice = uint64_t(this->Dims_[0]) * this->Dims_[1];
    for (uint32_t z = 0; z < this->Dims_[2]; ++z)
    {
      this->Factor_->UploadSlices(factor + slice * z, z, 1);
    }
  }
  this->FactorSerial_ = NewSerial();
}
}
