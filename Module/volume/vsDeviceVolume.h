// vsDeviceVolume.h — a scalar volume on the device: an R32F 3D storage image,
// uploaded once per change of the data. Non-finite voxels (NaN, +-Inf) are
// stored as NaN, which classifies to empty space; their count is reported.
//
// An integer-coded volume (every voxel finite and an integer at most 255 above the smallest, as
// 8-bit MRI and segmentations are) is also kept as quads: an R32UI image whose texel (x, y, z)
// packs the 8-bit codes (value - QuadOffset) of voxels (x, y), (x + 1, y), (x, y + 1),
// (x + 1, y + 1) of slice z (neighbours clamped to the volume), so that the render kernel reads a
// trilinear footprint in 2 vector gathers instead of 8 (lavapipe gathers 32-bit texels, and loads
// 8-bit ones lane by lane). The scalars the two give are the same floats. Such a volume's R32F image
// is made from the quads, on the device, only when a pass first asks for it (Image()): the render
// kernel under linear interpolation and the sweeps' pool read the quads alone, so a render that
// needs nothing else never holds the floats (issue 39: ch2better's 140 MB, which a CPU device faulted
// in during the first frame's upload: 0.3 s of it after an idle pause).
//
// Optionally a factor per voxel (the gradient opacity, vsGradientOpacity.h): a second R32F image of
// the same dimensions whose interpolant scales the classified extinction in every pass.
#ifndef vsDeviceVolume_h
#define vsDeviceVolume_h

#include "vissweepCoreModule.h"
#include "vsHostScalars.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>

namespace vs
{
class Context;
class Image3D;

class VISSWEEPCORE_EXPORT DeviceVolume
{
public:
  /** Called once per slice z with its dims[0] x dims[1] floats as uploaded (non-finite ones NaN),
   *  while they are in the cache; from the host's threads, several slices at once. */
  using SliceVisitor = std::function<void(uint32_t z, const float* slice)>;

  /** `scalars` holds dims[0]*dims[1]*dims[2] values, x fastest (floats, or the host's own type:
   *  vsHostScalars.h, read as floats slice by slice without a copy of the volume). Throws
   *  DeviceLimitError (too large for the device) or InputError (empty extent) before allocating.
   *  `eachSlice`, when given, sees every slice's floats (the brick ranges are made so). */
  DeviceVolume(std::shared_ptr<Context> context, const HostScalars& scalars, std::array<uint32_t, 3> dims,
    const SliceVisitor& eachSlice = SliceVisitor());
  ~DeviceVolume();

  /** The R32F image of the scalars. An integer-coded volume's is made from its quads on the first
   *  call (one dispatch); not thread-safe (device passes run on the render thread). */
  const Image3D& Image() const;
  /** Whether the R32F image exists yet (an integer-coded volume's is made on first use). */
  bool HasImage() const { return this->Image_ != nullptr; }
  /** The quads of an integer-coded volume, or nullptr (float data, quads over kMaxQuadBytes, or
   *  past the device's limits: they only speed the render kernel up, so a volume that fits without
   *  them renders without them). */
  const Image3D* Quads() const { return this->Quads_.get(); }
  /** The value of code 0 in the quads. */
  float QuadOffset() const { return this->QuadOffset_; }
  /** The largest quad image made (it doubles the volume's device memory). */
  static constexpr uint64_t kMaxQuadBytes = 256ull << 20;
  std::array<uint32_t, 3> Dims() const { return this->Dims_; }
  uint64_t NonFiniteCount() const { return this->NonFinite_; }
  /** The range of the finite voxels ([0,0] when none is finite). */
  std::array<float, 2> Range() const { return this->Range_; }

  /** Uploads the extinction factor per voxel (Dims() floats, x fastest, finite, >= 0), or drops it
   *  (nullptr). Each call gives a new FactorSerial(). */
  void SetFactor(const float* factor);
  /** The factor image, or nullptr (no factor: the extinction is the transfer function's). */
  const Image3D* Factor() const { return this->Factor_.get(); }
  /** Changes with every SetFactor (0: never set): what caches of the extinction compare. */
  uint64_t FactorSerial() const { return this->FactorSerial_; }

  /** Throws if a volume of these dimensions cannot live on the device. */
  static void CheckFits(Context& context, std::array<uint32_t, 3> dims);

private:
  std::shared_ptr<Context> Context_;
  std::array<uint32_t, 3> Dims_;
  mutable std::unique_ptr<Image3D> Image_; // made on first use when there are quads (Image())
  std::unique_ptr<Image3D> Factor_;
  uint64_t FactorSerial_ = 0;
  std::unique_ptr<Image3D> Quads_;
  float QuadOffset_ = 0.0f;
  uint64_t NonFinite_ = 0;
  std::array<float, 2> Range_{ { 0.0f, 0.0f } };
};
}

#endif
