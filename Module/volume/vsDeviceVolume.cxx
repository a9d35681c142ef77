#include "vsDeviceVolume.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsParallelSlabs.h"
#include "vsSerial.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vs
{
void DeviceVolume::CheckFits(Context& context, std::array<uint32_t, 3> dims)
{
  Image3D::CheckLimits(context, dims[0], dims[1], dims[2], vk::Format::eR32Sfloat, "volume");
}

DeviceVolume::DeviceVolume(std::shared_ptr<Context> context, const float* scalars, std::array<uint32_t, 3> dims)
  : Context_(context)
  , Dims_(dims)
{
  CheckFits(*context, dims);
  this->Image_ = std::make_unique<Image3D>(context, dims[0], dims[1], dims[2], vk::Format::eR32Sfloat, "volume");
  const uint64_t slice = uint64_t(dims[0]) * dims[1];
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Slabs of slices on the host's threads (vsParallelSlabs.h), each checking, staging and uploading its
  // own slices; the range, the integer test and the count combine over the slabs.
  struct Part
  {
    float Lo = std::numeric_limits<float>::max(), Hi = -std::numeric_limits<float>::max();
    bool Integral = true;
    uint64_t NonFinite = 0;
  };
  std::vector<Part> parts(SlabCount(dims[2]));
  ForSlabs(dims[2], [&](unsigned p, uint64_t z0, uint64_t z1) {
    Part& part = parts[p];
    std::vector<float> staging(slice);
    for (uint64_t z = z0; z < z1; ++z)
    {
      const float* src = scalars + slice * z;
      float lo = part.Lo, hi = part.Hi;
      bool integral = part.Integral;
      uint64_t nonFinite = 0;
      for (uint64_t i = 0; i < slice; ++i)
      {
        float v = src[i];
        if (std::isfinite(v))
        {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
          integral = integral && v == std::trunc(v);
        }
        else
        {
          ++nonFinite;
        }
      }
      part.Lo = lo;
      part.Hi = hi;
      part.Integral = integral;
      part.NonFinite += nonFinite;
      // A slice of finite voxels goes up as it is; non-finite ones become NaN in a copy.
      const float* upload = src;
      if (nonFinite)
      {
        for (uint64_t i = 0; i < slice; ++i)
        {
          staging[i] = std::isfinite(src[i]) ? src[i] : nan;
        }
        upload = staging.data();
      }
      this->Image_->UploadSlices(upload, uint32_t(z), 1);
    }
  });
  float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
  bool integral = true;
  for (const Part& part : parts)
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
      this->MakeQuads(context, scalars, lo);
    }
    catch (const DeviceLimitError&)
    {
      // The quads only speed the kernel up: a volume that fits without them renders without them.
      this->Quads_.reset();
    }
  }
}

void DeviceVolume::MakeQuads(const std::shared_ptr<Context>& context, const float* scalars, float offset)
{
  const auto& dims = this->Dims_;
  Image3D::CheckLimits(*context, dims[0], dims[1], dims[2], vk::Format::eR32Uint, "volume quads");
  this->Quads_ = std::make_unique<Image3D>(context, dims[0], dims[1], dims[2], vk::Format::eR32Uint, "volume quads");
  this->QuadOffset_ = offset;
  const uint64_t slice = uint64_t(dims[0]) * dims[1];
  ForSlabs(dims[2], [&](unsigned, uint64_t z0, uint64_t z1) {
    std::vector<uint8_t> codes(slice);
    std::vector<uint32_t> quads(slice);
    for (uint64_t z = z0; z < z1; ++z)
    {
      const float* src = scalars + slice * z;
      for (uint64_t i = 0; i < slice; ++i)
      {
        codes[i] = uint8_t(src[i] - offset);
      }
      for (uint32_t y = 0; y < dims[1]; ++y)
      {
        const uint8_t* row = codes.data() + uint64_t(y) * dims[0];
        const uint8_t* next = codes.data() + uint64_t(std::min(y + 1, dims[1] - 1)) * dims[0];
        uint32_t* out = quads.data() + uint64_t(y) * dims[0];
        const uint32_t last = dims[0] - 1;
        for (uint32_t x = 0; x < last; ++x)
        {
          out[x] = uint32_t(row[x]) | uint32_t(row[x + 1]) << 8 | uint32_t(next[x]) << 16 | uint32_t(next[x + 1]) << 24;
        }
        // The last column's right neighbour is itself (clamped).
        out[last] = uint32_t(row[last]) | uint32_t(row[last]) << 8 | uint32_t(next[last]) << 16 |
          uint32_t(next[last]) << 24;
      }
      this->Quads_->UploadSlices(quads.data(), uint32_t(z), 1);
    }
  });
}

DeviceVolume::~DeviceVolume() = default;

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
