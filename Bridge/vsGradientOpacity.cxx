#include "vsGradientOpacity.h"

#include "vtkPiecewiseFunction.h"
#include "vtkSMPTools.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace vs
{
bool HasEffectiveGradientOpacity(vtkVolumeProperty* property)
{
  if (!property || !property->HasGradientOpacity(0) || property->GetDisableGradientOpacity(0))
  {
    return false;
  }
  vtkPiecewiseFunction* f = property->GetStoredGradientOpacity(0);
  if (!f || f->GetSize() == 0)
  {
    return false;
  }
  if (!f->GetClamping())
  {
    return true; // 0 outside its points
  }
  for (int i = 0; i < f->GetSize(); ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    if (node[1] != 1.0)
    {
      return true;
    }
  }
  return false;
}

std::vector<double> GradientOpacitySignature(vtkVolumeProperty* property, const double spacing[3])
{
  std::vector<double> signature;
  if (!HasEffectiveGradientOpacity(property))
  {
    return signature;
  }
  vtkPiecewiseFunction* f = property->GetStoredGradientOpacity(0);
  signature.assign(spacing, spacing + 3);
  signature.push_back(f->GetClamping());
  for (int i = 0; i < f->GetSize(); ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    signature.insert(signature.end(), node, node + 4);
  }
  return signature;
}

namespace
{
// The derivative of the scalars along one axis at voxel i of a line of n voxels `stride` apart: the central
// difference, one-sided at the ends and where a neighbour is not finite, 0 where neither neighbour is.
inline double Derivative(const float* v, int64_t i, int64_t n, int64_t stride, double h)
{
  const float c = v[0];
  const bool back = i > 0 && std::isfinite(v[-stride]);
  const bool ahead = i + 1 < n && std::isfinite(v[stride]);
  if (back && ahead)
  {
    return (double(v[stride]) - double(v[-stride])) / (2.0 * h);
  }
  if (ahead)
  {
    return (double(v[stride]) - double(c)) / h;
  }
  if (back)
  {
    return (double(c) - double(v[-stride])) / h;
  }
  return 0.0;
}
} // namespace

std::vector<float> GradientOpacityFactor(const float* scalars, std::array<uint32_t, 3> dims, const double spacing[3],
  vtkPiecewiseFunction* gradientOpacity, size_t entries)
{
  const int64_t nx = dims[0], ny = dims[1], nz = dims[2];
  const size_t count = size_t(nx) * size_t(ny) * size_t(nz);
  std::vector<float> factor(count, 0.0f);
  const double h[3] = { std::abs(spacing[0]) > 0.0 ? std::abs(spacing[0]) : 1.0,
    std::abs(spacing[1]) > 0.0 ? std::abs(spacing[1]) : 1.0, std::abs(spacing[2]) > 0.0 ? std::abs(spacing[2]) : 1.0 };
  // The magnitudes first (into the factor array), then GO of each through a table over their range.
  vtkSMPTools::For(0, nz,
    [&](int64_t z0, int64_t z1)
    {
      for (int64_t z = z0; z < z1; ++z)
      {
        for (int64_t y = 0; y < ny; ++y)
        {
          for (int64_t x = 0; x < nx; ++x)
          {
            const int64_t i = (z * ny + y) * nx + x;
            const float* v = scalars + i;
            if (!std::isfinite(*v))
            {
              factor[size_t(i)] = -1.0f; // no sample reads it: g = 0 below
              continue;
            }
            const double gx = Derivative(v, x, nx, 1, h[0]);
            const double gy = Derivative(v, y, ny, nx, h[1]);
            const double gz = Derivative(v, z, nz, nx * ny, h[2]);
            factor[size_t(i)] = float(std::min(std::sqrt(gx * gx + gy * gy + gz * gz), 3.0e38));
          }
        }
      }
    });
  float largest = 0.0f;
  for (float m : factor)
  {
    largest = std::max(largest, m);
  }
  entries = std::max<size_t>(entries, 2);
  std::vector<double> table(entries);
  const double top = largest > 0.0f ? double(largest) : 1.0;
  gradientOpacity->GetTable(0.0, top, int(entries), table.data());
  for (double& t : table)
  {
    t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  }
  const double scale = double(entries - 1) / top;
  vtkSMPTools::For(0, int64_t(count),
    [&](int64_t i0, int64_t i1)
    {
      for (int64_t i = i0; i < i1; ++i)
      {
        const float m = factor[size_t(i)];
        if (m < 0.0f)
        {
          factor[size_t(i)] = 0.0f;
          continue;
        }
        const double x = std::min(double(m) * scale, double(entries - 1));
        const size_t k = std::min(size_t(x), entries - 2);
        const double f = x - double(k);
        factor[size_t(i)] = float(table[k] + f * (table[k + 1] - table[k]));
      }
    });
  return factor;
}
} // namespace vs
