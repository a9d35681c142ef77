// vsDeviceVolume.h — a scalar volume on the device: an R32F 3D storage image,
// uploaded once per change of the data. Non-finite voxels (NaN, +-Inf) are
// stored as NaN, which classifies to empty space; their count is reported.
#ifndef vsDeviceVolume_h
#define vsDeviceVolume_h

#include "vissweepCoreModule.h"

#include <array>
#include <cstdint>
#include <memory>

namespace vs
{
class Context;
class Image3D;

class VISSWEEPCORE_EXPORT DeviceVolume
{
public:
  /** `scalars` holds dims[0]*dims[1]*dims[2] floats, x fastest. Throws DeviceLimitError
   *  (too large for the device) or InputError (empty extent) before allocating. */
  DeviceVolume(std::shared_ptr<Context> context, const float* scalars, std::array<uint32_t, 3> dims);
  ~DeviceVolume();

  const Image3D& Image() const { return *this->Image_; }
  std::array<uint32_t, 3> Dims() const { return this->Dims_; }
  uint64_t NonFiniteCount() const { return this->NonFinite_; }
  /** The range of the finite voxels ([0,0] when none is finite). */
  std::array<float, 2> Range() const { return this->Range_; }

  /** Throws if a volume of these dimensions cannot live on the device. */
  static void CheckFits(Context& context, std::array<uint32_t, 3> dims);

private:
  std::array<uint32_t, 3> Dims_;
  std::unique_ptr<Image3D> Image_;
  uint64_t NonFinite_ = 0;
  std::array<float, 2> Range_{ { 0.0f, 0.0f } };
};
}

#endif
