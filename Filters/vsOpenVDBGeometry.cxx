// vsOpenVDBGeometry.cxx — the axis-aligned form of a grid's transform and the output image of a
// time step (vsOpenVDBGeometry.h).
#include "vsOpenVDBGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

namespace vs
{
bool GetAxisMap(const openvdb::math::Transform& xform, AxisMap& map, std::string& why)
{
  if (!xform.isLinear())
  {
    why = "its transform is a " + xform.mapType() +
      " (not linear): non-axis-aligned transforms are not supported yet";
    return false;
  }
  const openvdb::Mat4d m = xform.baseMap()->getAffineMap()->getMat4();
  double largest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    largest = std::max(largest, std::abs(m(a, a)));
  }
  // OpenVDB's matrices act on row vectors: world = [i j k 1] * M, M(3, a) is the translation.
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (r != c && !(std::abs(m(r, c)) <= 1e-9 * largest))
      {
        std::ostringstream s;
        s << "its " << xform.mapType()
          << " index-to-world transform rotates or shears the index axes (matrix " << m
          << "): non-axis-aligned transforms are not supported yet";
        why = s.str();
        return false;
      }
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    map.Scale[a] = m(a, a);
    map.Translation[a] = m(3, a);
    if (!(map.Scale[a] != 0.0) || !std::isfinite(map.Scale[a]) ||
      !std::isfinite(map.Translation[a]))
    {
      std::ostringstream s;
      s << "its transform is degenerate (matrix " << m << ")";
      why = s.str();
      return false;
    }
  }
  return true;
}

bool SameTransform(const openvdb::Mat4d& a, const openvdb::Mat4d& b)
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double tol = 1e-12 * std::max({ 1.0, std::abs(a(r, c)), std::abs(b(r, c)) });
      if (!(std::abs(a(r, c) - b(r, c)) <= tol))
      {
        return false;
      }
    }
  }
  return true;
}

bool MakeOutputGeometry(const openvdb::CoordBBox& box, const AxisMap& map, int padding,
  vtkIdType maxPoints, OutputGeometry& g, std::string& error)
{
  g = OutputGeometry();
  g.Empty = box.empty();
  vtkIdType points = 1;
  int64_t lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = (g.Empty ? 0 : int64_t(box.min()[a])) - padding;
    hi[a] = (g.Empty ? 0 : int64_t(box.max()[a])) + padding;
    const int64_t n = hi[a] - lo[a] + 1;
    if (lo[a] < std::numeric_limits<int32_t>::min() ||
      hi[a] > std::numeric_limits<int32_t>::max() || n > VTK_INT_MAX || points > maxPoints / n)
    {
      std::ostringstream s;
      s << "the output would cover index box " << box << " plus " << padding
        << " voxels of padding, more than MaximumNumberOfPoints (" << maxPoints << ")";
      error = s.str();
      return false;
    }
    points *= n;
    g.Extent[2 * a] = 0;
    g.Extent[2 * a + 1] = int(n - 1);
    const double s = map.Scale[a];
    g.Flip[a] = s < 0;
    // Point p of the image is voxel lo + p (or hi - p on a flipped axis), centred at
    // Translation + Scale * index.
    g.Origin[a] = map.Translation[a] + s * double(g.Flip[a] ? hi[a] : lo[a]);
    g.Spacing[a] = std::abs(s);
  }
  g.Region = openvdb::CoordBBox(openvdb::Coord(int(lo[0]), int(lo[1]), int(lo[2])),
    openvdb::Coord(int(hi[0]), int(hi[1]), int(hi[2])));
  g.Points = points;
  return true;
}
}
