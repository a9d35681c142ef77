#include "vsDeviceVolume.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"

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
  }
  if (lo <= hi)
  {
    this->Range_ = { { lo, hi } };
  }
}

DeviceVolume::~DeviceVolume() = default;
}
