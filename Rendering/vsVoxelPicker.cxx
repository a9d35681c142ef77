#include "vsVoxelPicker.h"

#include "vtkDataArray.h"
#include "vtkPiecewiseFunction.h"

#include <algorithm>
#include <cmath>

namespace vs
{
namespace
{
// The scalar (or, with `factor`, the extinction factor) at continuous index p (voxel centres at
// integers), NaN outside the grid.
double Sample(const VoxelPicker::Volume& v, const glm::dvec3& p, const std::vector<float>* factor = nullptr)
{
  const auto& d = v.Geometry.Dims;
  auto at = [&](int i, int j, int k) {
    const vtkIdType id = (vtkIdType(k) * d[1] + j) * d[0] + i;
    return factor ? double((*factor)[size_t(id)]) : v.Scalars->GetComponent(id, 0);
  };
  if (v.Nearest)
  {
    int ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = std::clamp(int(std::floor(p[a] + 0.5)), 0, int(d[a]) - 1);
    }
    return at(ijk[0], ijk[1], ijk[2]);
  }
  int lo[3], hi[3];
  double f[3];
  for (int a = 0; a < 3; ++a)
  {
    const double c = std::clamp(p[a], 0.0, double(d[a] - 1));
    lo[a] = std::min(int(std::floor(c)), int(d[a]) - 1);
    hi[a] = std::min(lo[a] + 1, int(d[a]) - 1);
    f[a] = c - lo[a];
  }
  double s = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    double w = 1.0;
    int ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      const bool up = (corner >> a) & 1;
      ijk[a] = up ? hi[a] : lo[a];
      w *= up ? f[a] : 1.0 - f[a];
    }
    if (w > 0.0)
    {
      s += w * at(ijk[0], ijk[1], ijk[2]);
    }
  }
  return s;
}

double Extinction(const VoxelPicker::Volume& v, double s)
{
  if (!std::isfinite(s))
  {
    return 0.0; // NaN voxels are empty space, as in the renderer
  }
  const double alpha = std::clamp(v.Opacity->GetValue(s), 0.0, 1.0 - 1e-7);
  return -std::log1p(-alpha) / std::max(v.UnitDistance, 1e-30) * v.DensityScale;
}

vtkIdType IdOf(const VoxelPicker::Volume& v, const glm::dvec3& p, bool cells)
{
  const auto& d = v.Geometry.Dims;
  if (cells)
  {
    int c[3], n[3];
    for (int a = 0; a < 3; ++a)
    {
      n[a] = std::max(int(d[a]) - 1, 1);
      c[a] = std::clamp(int(std::floor(p[a])), 0, n[a] - 1);
    }
    return (vtkIdType(c[2]) * n[1] + c[1]) * n[0] + c[0];
  }
  int q[3];
  for (int a = 0; a < 3; ++a)
  {
    q[a] = std::clamp(int(std::floor(p[a] + 0.5)), 0, int(d[a]) - 1);
  }
  return (vtkIdType(q[2]) * d[1] + q[1]) * d[0] + q[0];
}
}

std::vector<vtkIdType> VoxelPicker::Ids(const Volume& v, const glm::dmat4& invViewProj, int width, int height,
  const std::vector<float>& depth, const std::vector<bool>& covered, double threshold, bool cells)
{
  std::vector<vtkIdType> ids(size_t(std::max(0, width)) * std::max(0, height), -1);
  if (!v.Scalars || !v.Opacity || width <= 0 || height <= 0)
  {
    return ids;
  }
  const double tauHit = -std::log1p(-threshold); // opacity 1 - exp(-tau) > threshold
  const glm::dvec3 boxMin(v.Geometry.BoxMin), boxMax(v.Geometry.BoxMax);
  const double step = 0.5 * v.Geometry.MinSpacing;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const size_t pixel = size_t(y) * width + x;
      if (pixel >= covered.size() || !covered[pixel])
      {
        continue;
      }
      const glm::dvec2 ndc((x + 0.5) / width * 2.0 - 1.0, (y + 0.5) / height * 2.0 - 1.0);
      const glm::dvec4 pn = invViewProj * glm::dvec4(ndc, -1.0, 1.0), pf = invViewProj * glm::dvec4(ndc, 1.0, 1.0);
      const glm::dvec3 ow = glm::dvec3(pn) / pn.w;
      const glm::dvec3 dw = glm::normalize(glm::dvec3(pf) / pf.w - ow);
      double tEnd = 1e300;
      const float z = pixel < depth.size() ? depth[pixel] : 1.0f;
      if (z < 1.0f)
      {
        const glm::dvec4 pd = invViewProj * glm::dvec4(ndc, 2.0 * z - 1.0, 1.0);
        tEnd = glm::dot(glm::dvec3(pd) / pd.w - ow, dw);
      }
      // The ray's interval in the box (index space; t stays in world units).
      const glm::dvec3 o = glm::dvec3(v.Geometry.WorldToIndex * glm::dvec4(ow, 1.0));
      const glm::dvec3 d = glm::dvec3(v.Geometry.WorldToIndex * glm::dvec4(dw, 0.0));
      double t0 = 0.0, t1 = tEnd;
      for (int a = 0; a < 3 && t0 <= t1; ++a)
      {
        if (std::abs(d[a]) < 1e-300)
        {
          if (o[a] < boxMin[a] || o[a] > boxMax[a])
          {
            t1 = -1.0;
          }
          continue;
        }
        double ta = (boxMin[a] - o[a]) / d[a], tb = (boxMax[a] - o[a]) / d[a];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
      }
      double tau = 0.0;
      for (double t = t0 + 0.5 * step; t < t1; t += step)
      {
        const glm::dvec3 w = ow + t * dw;
        bool clipped = false;
        for (const glm::dvec4& plane : v.WorldPlanes)
        {
          clipped = clipped || glm::dot(glm::dvec3(plane), w) + plane.w < 0.0;
        }
        if (clipped)
        {
          continue;
        }
        const glm::dvec3 p = o + t * d;
        const double sigma = Extinction(v, Sample(v, p));
        tau += (v.Factor && sigma > 0.0 ? sigma * Sample(v, p, v.Factor) : sigma) * step;
        if (tau > tauHit)
        {
          ids[pixel] = IdOf(v, p, cells);
          break;
        }
      }
    }
  }
  return ids;
}
}
