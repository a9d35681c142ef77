// vsBrickRanges.h — the scalar range of every brick of B^3 voxels (MajorantGrid::Ranges) made on the
// host slice by slice: per brick b the min, max and a non-finite flag over voxels [bB, (b+1)B]
// (inclusive, clamped to the volume), as majorant_minmax.comp computes them on the device.
// AddSlice reduces a slice's rows to its spans per (brick x, brick y) at once, so the device volume's
// upload can feed it the slices it converts while they are in the cache (issue 39: the ranges were a
// second pass over ch2better's 141 MB of floats); Finish reduces along z. Min, max and the flag are
// exact, so the result does not depend on the order or the threads the slices came from.
#ifndef vsBrickRanges_h
#define vsBrickRanges_h

#include "vissweepCoreModule.h"

#include <array>
#include <cstdint>
#include <vector>

namespace vs
{
class VISSWEEPCORE_EXPORT BrickRanges
{
public:
  BrickRanges(std::array<uint32_t, 3> dims, uint32_t brickSize);

  /** Bricks per axis for a volume of `dims` voxels: a brick covers voxels [bB, (b+1)B], the last
   *  voxel index is dims - 1; at least 1. */
  static std::array<uint32_t, 3> Bricks(std::array<uint32_t, 3> dims, uint32_t brickSize);

  /** Slice z's dims[0] x dims[1] scalars (x fastest; non-finite ones are empty space). Each z once;
   *  calls for different z may come from different threads at once. */
  void AddSlice(uint32_t z, const float* slice);

  /** Per brick (x fastest): min, max ((1, 0) where no voxel is finite), 1 where a voxel is not finite
   *  (else 0), 0. Every slice must have been added. */
  std::vector<float> Finish() const;

  std::array<uint32_t, 3> Dims() const { return this->Dims_; }
  uint32_t BrickSize() const { return this->BrickSize_; }

private:
  struct Span
  {
    float Min = 3.4e38f, Max = -3.4e38f;
    bool Gap = false;
  };
  std::array<uint32_t, 3> Dims_, Bricks_;
  uint32_t BrickSize_;
  std::vector<Span> Planes_; // (brick x, brick y, z)
};
}

#endif
