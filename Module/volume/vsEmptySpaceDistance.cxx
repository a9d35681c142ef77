#include "vsEmptySpaceDistance.h"

#include <algorithm>

namespace vs
{
std::vector<float> EmptySpaceDistance(
  const std::vector<float>& majorants, std::array<uint32_t, 3> bricks, uint32_t cap)
{
  const int64_t nx = bricks[0], ny = bricks[1], nz = bricks[2];
  std::vector<uint32_t> d(majorants.size());
  for (size_t i = 0; i < d.size(); ++i)
  {
    d[i] = majorants[i] != 0.0f ? 0u : cap; // NaN majorants are not 0: never skipped
  }
  auto at = [&](int64_t x, int64_t y, int64_t z) -> uint32_t& { return d[size_t((z * ny + y) * nx + x)]; };
  // The chessboard distance is a chamfer distance with unit weights on all 26 neighbours; one
  // forward raster pass over the 13 neighbours before a brick and one backward pass over the 13
  // after it give it exactly.
  auto relax = [&](int64_t x, int64_t y, int64_t z, int sign) {
    uint32_t& v = at(x, y, z);
    if (v == 0)
    {
      return;
    }
    for (int dz = -1; dz <= 1; ++dz)
    {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          // The neighbours already visited in this pass's raster order.
          const int order = (dz * 3 + dy) * 3 + dx;
          if (sign * order >= 0)
          {
            continue;
          }
          const int64_t X = x + dx, Y = y + dy, Z = z + dz;
          if (X < 0 || Y < 0 || Z < 0 || X >= nx || Y >= ny || Z >= nz)
          {
            continue;
          }
          v = std::min(v, at(X, Y, Z) + 1u);
        }
      }
    }
  };
  for (int64_t z = 0; z < nz; ++z)
    for (int64_t y = 0; y < ny; ++y)
      for (int64_t x = 0; x < nx; ++x)
        relax(x, y, z, +1);
  for (int64_t z = nz - 1; z >= 0; --z)
    for (int64_t y = ny - 1; y >= 0; --y)
      for (int64_t x = nx - 1; x >= 0; --x)
        relax(x, y, z, -1);
  return std::vector<float>(d.begin(), d.end());
}
}
