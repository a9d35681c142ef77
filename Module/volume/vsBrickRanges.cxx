#include "vsBrickRanges.h"
#include "vsError.h"
#include "vsParallelSlabs.h"

#include <algorithm>
#include <cmath>

namespace vs
{
std::array<uint32_t, 3> BrickRanges::Bricks(std::array<uint32_t, 3> dims, uint32_t brickSize)
{
  std::array<uint32_t, 3> bricks;
  for (int i = 0; i < 3; ++i)
  {
    bricks[i] = std::max<uint32_t>(1, (dims[i] - 1 + brickSize - 1) / brickSize);
  }
  return bricks;
}

BrickRanges::BrickRanges(std::array<uint32_t, 3> dims, uint32_t brickSize)
  : Dims_(dims)
  , BrickSize_(brickSize)
{
  if (brickSize < 1)
  {
    throw InputError("the majorant brick size must be at least 1 voxel");
  }
  this->Bricks_ = Bricks(dims, brickSize);
  this->Planes_.resize(size_t(this->Bricks_[0]) * this->Bricks_[1] * dims[2]);
}

void BrickRanges::AddSlice(uint32_t z, const float* slice)
{
  const size_t nx = this->Dims_[0], ny = this->Dims_[1];
  const size_t bx = this->Bricks_[0], by = this->Bricks_[1], B = this->BrickSize_;
  auto lo = [&](size_t b) { return b * B; };
  auto hi = [&](size_t b, size_t n) { return std::min<size_t>(b * B + B, n - 1); };
  Span* plane = this->Planes_.data() + size_t(z) * bx * by;
  std::fill(plane, plane + bx * by, Span());
  for (size_t y = 0; y < ny; ++y)
  {
    const float* row = slice + y * nx;
    // Row y belongs to brick y / B, and to the brick before when it is that brick's last row.
    const size_t b1 = std::min(y / B, by - 1);
    const size_t b0 = (y % B == 0 && y >= B) ? y / B - 1 : b1;
    for (size_t b = 0; b < bx; ++b)
    {
      Span s;
      for (size_t x = lo(b); x <= hi(b, nx); ++x)
      {
        const float f = row[x];
        if (!std::isfinite(f)) // stored as NaN on the device: empty space
        {
          s.Gap = true;
        }
        else
        {
          s.Min = std::min(s.Min, f);
          s.Max = std::max(s.Max, f);
        }
      }
      for (size_t c = b0; c <= b1; ++c)
      {
        if (y < lo(c) || y > hi(c, ny))
        {
          continue;
        }
        Span& p = plane[c * bx + b];
        p.Min = std::min(p.Min, s.Min);
        p.Max = std::max(p.Max, s.Max);
        p.Gap = p.Gap || s.Gap;
      }
    }
  }
}

std::vector<float> BrickRanges::Finish() const
{
  const size_t nz = this->Dims_[2];
  const size_t bx = this->Bricks_[0], by = this->Bricks_[1], bz = this->Bricks_[2], B = this->BrickSize_;
  std::vector<float> ranges(4 * bx * by * bz);
  ForSlabs(bz, [&](unsigned, uint64_t b0, uint64_t b1) {
    for (size_t b = b0; b < b1; ++b)
    {
      for (size_t y = 0; y < by; ++y)
      {
        for (size_t x = 0; x < bx; ++x)
        {
          Span s;
          for (size_t z = b * B; z <= std::min<size_t>(b * B + B, nz - 1); ++z)
          {
            const Span& p = this->Planes_[(z * by + y) * bx + x];
            s.Min = std::min(s.Min, p.Min);
            s.Max = std::max(s.Max, p.Max);
            s.Gap = s.Gap || p.Gap;
          }
          float* r = &ranges[4 * ((b * by + y) * bx + x)];
          const bool any = s.Min <= s.Max;
          r[0] = any ? s.Min : 1.0f;
          r[1] = any ? s.Max : 0.0f;
          r[2] = s.Gap ? 1.0f : 0.0f;
          r[3] = 0.0f;
        }
      }
    }
  });
  return ranges;
}
}
