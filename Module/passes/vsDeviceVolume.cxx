#include "vsDeviceVolume.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"

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
  : Dims_(dims)
{
  CheckFits(*context, dims);
  this->Image_ = std::make_unique<Image3D>(context, dims[0], dims[1], dims[2], vk::Format::eR32Sfloat, "volume");
  const uint64_t slice = uint64_t(dims[0]) * dims[1];
  const uint64_t voxels = slice * dims[2];
  // Integer-coded: finite integers spanning at most 255 (quads of 8-bit codes, see the header).
  bool coded = voxels * 4 <= kMaxQuadBytes;
  float codeLo = std::numeric_limits<float>::max(), codeHi = -std::numeric_limits<float>::max();
  for (uint64_t i = 0; coded && i < voxels; ++i)
  {
    const float v = scalars[i];
    coded = std::isfinite(v) && v == std::floor(v) && std::abs(v) < 16777216.0f;
    codeLo = std::min(codeLo, v);
    codeHi = std::max(codeHi, v);
  }
  coded = coded && codeHi - codeLo <= 255.0f;
  std::vector<uint32_t> quads;
  if (coded)
  {
    Image3D::CheckLimits(*context, dims[0], dims[1], dims[2], vk::Format::eR32Uint, "volume quads");
    this->Quads_ = std::make_unique<Image3D>(context, dims[0], dims[1], dims[2], vk::Format::eR32Uint, "volume quads");
    this->QuadOffset_ = codeLo;
    quads.resize(slice);
  }
  std::vector<float> staging(slice);
  float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (uint32_t z = 0; z < dims[2]; ++z)
  {
    const float* src = scalars + slice * z;
    for (uint64_t i = 0; i < slice; ++i)
    {
      float v = src[i];
      if (std::isfinite(v))
      {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        staging[i] = v;
      }
      else
      {
        staging[i] = nan;
        ++this->NonFinite_;
      }
    }
    this->Image_->UploadSlices(staging.data(), z, 1);
    if (coded)
    {
      auto code = [&](uint32_t x, uint32_t y) {
        return uint32_t(src[uint64_t(y) * dims[0] + x] - codeLo);
      };
      for (uint32_t y = 0; y < dims[1]; ++y)
      {
        const uint32_t y1 = std::min(y + 1, dims[1] - 1);
        for (uint32_t x = 0; x < dims[0]; ++x)
        {
          const uint32_t x1 = std::min(x + 1, dims[0] - 1);
          quads[uint64_t(y) * dims[0] + x] = code(x, y) | code(x1, y) << 8 | code(x, y1) << 16 | code(x1, y1) << 24;
        }
      }
      this->Quads_->UploadSlices(quads.data(), z, 1);
    }
  }
  if (lo <= hi)
  {
    this->Range_ = { { lo, hi } };
  }
}

DeviceVolume::~DeviceVolume() = default;
}
