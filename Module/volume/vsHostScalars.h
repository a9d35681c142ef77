// vsHostScalars.h — a volume's scalars as the host holds them (x fastest, one component): a
// pointer into the caller's memory and its element type. The device volume reads each value as
// float(double(v)), as VTK's GetComponent does (an int64 above 2^53 rounds the same way), slice by
// slice while it uploads: no float copy of the whole volume is made (issue 39: 35 M voxels of 8-bit
// MRI became a 141 MB float vector before the upload, a third of the first frame).
#ifndef vsHostScalars_h
#define vsHostScalars_h

#include "vissweepCoreModule.h"

#include <cstdint>

namespace vs
{
struct VISSWEEPCORE_EXPORT HostScalars
{
  enum class Type
  {
    Float32,
    Float64,
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Int64,
    UInt64
  };

  HostScalars() = default;
  /** Floats (the type every caller had before). */
  HostScalars(const float* data)
    : Data(data)
  {
  }
  HostScalars(const void* data, Type type)
    : Data(data)
    , Kind(type)
  {
  }

  const void* Data = nullptr; // null: none (the caller converts to floats itself)
  Type Kind = Type::Float32;

  /** Whether the type holds integers only (every value finite and integer-valued as a float). */
  bool Integer() const { return this->Kind != Type::Float32 && this->Kind != Type::Float64; }

  /** The finite values' range of items [begin, end) as floats (lo > hi when none is finite), whether
   *  every finite value is an integer, and how many are not finite. */
  struct Summary
  {
    float Lo, Hi;
    bool Integral;
    uint64_t NonFinite;
  };
  Summary Summarize(uint64_t begin, uint64_t end) const;

  /** Items [begin, end) as floats into out[0, end - begin), non-finite ones as NaN (the device
   *  volume's convention: empty space). */
  void ToFloat(uint64_t begin, uint64_t end, float* out) const;
};
}

#endif
