#include "vsHostScalars.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vs
{
namespace
{
template <typename T>
float AsFloat(T v)
{
  return static_cast<float>(static_cast<double>(v));
}

// Integers: no value is non-finite or fractional; the range in the type, then as floats (the
// conversion is monotone, so the float of the smallest is the smallest float).
template <typename T>
HostScalars::Summary SummarizeIntegers(const T* v, uint64_t begin, uint64_t end)
{
  if (begin >= end)
  {
    return { std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), true, 0 };
  }
  T lo = v[begin], hi = v[begin];
  for (uint64_t i = begin + 1; i < end; ++i)
  {
    lo = std::min(lo, v[i]);
    hi = std::max(hi, v[i]);
  }
  return { AsFloat(lo), AsFloat(hi), true, 0 };
}

template <typename T>
HostScalars::Summary SummarizeReals(const T* v, uint64_t begin, uint64_t end)
{
  HostScalars::Summary s{ std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), true, 0 };
  for (uint64_t i = begin; i < end; ++i)
  {
    const float f = AsFloat(v[i]);
    if (std::isfinite(f))
    {
      s.Lo = std::min(s.Lo, f);
      s.Hi = std::max(s.Hi, f);
      s.Integral = s.Integral && f == std::trunc(f);
    }
    else
    {
      ++s.NonFinite;
    }
  }
  return s;
}

template <typename T>
void IntegersToFloat(const T* v, uint64_t begin, uint64_t end, float* out)
{
  for (uint64_t i = begin; i < end; ++i)
  {
    *out++ = AsFloat(v[i]);
  }
}

template <typename T>
void RealsToFloat(const T* v, uint64_t begin, uint64_t end, float* out)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (uint64_t i = begin; i < end; ++i)
  {
    const float f = AsFloat(v[i]);
    *out++ = std::isfinite(f) ? f : nan;
  }
}
}

HostScalars::Summary HostScalars::Summarize(uint64_t begin, uint64_t end) const
{
  switch (this->Kind)
  {
    case Type::Float32:
      return SummarizeReals(static_cast<const float*>(this->Data), begin, end);
    case Type::Float64:
      return SummarizeReals(static_cast<const double*>(this->Data), begin, end);
    case Type::Int8:
      return SummarizeIntegers(static_cast<const int8_t*>(this->Data), begin, end);
    case Type::UInt8:
      return SummarizeIntegers(static_cast<const uint8_t*>(this->Data), begin, end);
    case Type::Int16:
      return SummarizeIntegers(static_cast<const int16_t*>(this->Data), begin, end);
    case Type::UInt16:
      return SummarizeIntegers(static_cast<const uint16_t*>(this->Data), begin, end);
    case Type::Int32:
      return SummarizeIntegers(static_cast<const int32_t*>(this->Data), begin, end);
    case Type::UInt32:
      return SummarizeIntegers(static_cast<const uint32_t*>(this->Data), begin, end);
    case Type::Int64:
      return SummarizeIntegers(static_cast<const int64_t*>(this->Data), begin, end);
    case Type::UInt64:
      return SummarizeIntegers(static_cast<const uint64_t*>(this->Data), begin, end);
  }
  return { std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), true, 0 };
}

void HostScalars::ToFloat(uint64_t begin, uint64_t end, float* out) const
{
  switch (this->Kind)
  {
    case Type::Float32:
      return RealsToFloat(static_cast<const float*>(this->Data), begin, end, out);
    case Type::Float64:
      return RealsToFloat(static_cast<const double*>(this->Data), begin, end, out);
    case Type::Int8:
      return IntegersToFloat(static_cast<const int8_t*>(this->Data), begin, end, out);
    case Type::UInt8:
      return IntegersToFloat(static_cast<const uint8_t*>(this->Data), begin, end, out);
    case Type::Int16:
      return IntegersToFloat(static_cast<const int16_t*>(this->Data), begin, end, out);
    case Type::UInt16:
      return IntegersToFloat(static_cast<const uint16_t*>(this->Data), begin, end, out);
    case Type::Int32:
      return IntegersToFloat(static_cast<const int32_t*>(this->Data), begin, end, out);
    case Type::UInt32:
      return IntegersToFloat(static_cast<const uint32_t*>(this->Data), begin, end, out);
    case Type::Int64:
      return IntegersToFloat(static_cast<const int64_t*>(this->Data), begin, end, out);
    case Type::UInt64:
      return IntegersToFloat(static_cast<const uint64_t*>(this->Data), begin, end, out);
  }
}
}
