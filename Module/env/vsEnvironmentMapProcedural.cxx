// vsEnvironmentMapProcedural.cxx — procedural environment maps (Constant, TwoToneSky, SunDisk)
// whose texels are exact means over their solid angle: the horizon clips each texel's square
// against the octahedral diamond, and a sun disk's coverage of a texel comes from adaptive
// subdivision with an exact clip in the leaves. The map itself is in vsEnvironmentMap.cxx.
#include "vsEnvironmentMap.h"

#include "sampling/octahedral.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace vs
{
namespace
{
constexpr double Pi = glm::pi<double>();

/* Angle between two directions (unit or not), accurate for small angles. */
double Angle(glm::dvec3 a, glm::dvec3 b)
{
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

/* Area of the convex polygon poly clipped to the half-plane dot(n, p) <= c
 * (one Sutherland-Hodgman step). */
std::vector<glm::dvec2> ClipHalfPlane(const std::vector<glm::dvec2>& poly, glm::dvec2 n, double c)
{
  std::vector<glm::dvec2> out;
  for (std::size_t i = 0; i < poly.size(); ++i)
  {
    const glm::dvec2 p = poly[i], q = poly[(i + 1) % poly.size()];
    const double dp = glm::dot(n, p) - c, dq = glm::dot(n, q) - c;
    if (dp <= 0.0)
    {
      out.push_back(p);
    }
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0))
    {
      out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
  }
  return out;
}

double PolygonArea(const std::vector<glm::dvec2>& poly)
{
  double area = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i)
  {
    const glm::dvec2& p = poly[i];
    const glm::dvec2& q = poly[(i + 1) % poly.size()];
    area += p.x * q.y - q.x * p.y;
  }
  return 0.5 * std::abs(area);
}

std::vector<glm::dvec2> Square(double x0, double y0, double x1, double y1)
{
  return { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } };
}

/* Area of the part of the axis-aligned square [x0,x1]x[y0,y1] with |x|+|y| < 1. */
double SquareInDiamondArea(double x0, double y0, double x1, double y1)
{
  std::vector<glm::dvec2> poly = Square(x0, y0, x1, y1);
  const glm::dvec2 normals[4] = { { 1, 1 }, { -1, 1 }, { 1, -1 }, { -1, -1 } };
  for (const glm::dvec2& nrm : normals)
  {
    poly = ClipHalfPlane(poly, nrm, 1.0);
    if (poly.empty())
    {
      return 0.0;
    }
  }
  return PolygonArea(poly);
}

/* Fraction of the solid angle of the octahedral rectangle [u0,u1]x[v0,v1] that lies
 * within angle r of direction s: adaptive subdivision until the cells are small
 * against r; in a leaf cell the angle to s is linearized (its gradient from the
 * edge midpoints) and the cell is clipped exactly by the resulting straight edge
 * (the map is equal-area, so uv area is solid angle). */
struct DiskCoverage
{
  glm::dvec3 S;
  double R;

  double Rect(double u0, double v0, double u1, double v1, int depth) const
  {
    const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
    const glm::dvec3 c(OctahedralToDirection(um, vm));
    const double delta = Angle(c, this->S);
    // A bound of the rectangle's angular radius around its centre, from its
    // corners and edge midpoints, with a safety margin for the map's curvature.
    const double pu[8] = { u0, u1, u0, u1, um, um, u0, u1 };
    const double pv[8] = { v0, v0, v1, v1, v0, v1, vm, vm };
    double rho = 0.0;
    for (int i = 0; i < 8; ++i)
    {
      rho = std::max(rho, Angle(c, glm::dvec3(OctahedralToDirection(pu[i], pv[i]))));
    }
    rho = std::min(Pi, 1.5 * rho);
    if (delta - rho >= this->R)
    {
      return 0.0;
    }
    if (delta + rho <= this->R)
    {
      return 1.0;
    }
    // Equal-area map: the rectangle's solid angle is 4 pi times its uv area.
    const double width = std::sqrt(4.0 * Pi * (u1 - u0) * (v1 - v0));
    if (width < this->R / 16.0 || depth >= 22)
    {
      const double gu = (Angle(glm::dvec3(OctahedralToDirection(u1, vm)), this->S) -
                          Angle(glm::dvec3(OctahedralToDirection(u0, vm)), this->S)) / (u1 - u0);
      const double gv = (Angle(glm::dvec3(OctahedralToDirection(um, v1)), this->S) -
                          Angle(glm::dvec3(OctahedralToDirection(um, v0)), this->S)) / (v1 - v0);
      const double hu = 0.5 * (u1 - u0), hv = 0.5 * (v1 - v0);
      // Inside where delta + gu (u - um) + gv (v - vm) < R.
      const std::vector<glm::dvec2> in =
        ClipHalfPlane(Square(-hu, -hv, hu, hv), glm::dvec2(gu, gv), this->R - delta);
      return in.empty() ? 0.0 : std::min(1.0, PolygonArea(in) / (4.0 * hu * hv));
    }
    return 0.25 *
      (this->Rect(u0, v0, um, vm, depth + 1) + this->Rect(um, v0, u1, vm, depth + 1) +
        this->Rect(u0, vm, um, v1, depth + 1) + this->Rect(um, vm, u1, v1, depth + 1));
  }
};
} // namespace

EnvironmentMap EnvironmentMap::Constant(int size, glm::vec3 rgb)
{
  EnvironmentMap map = Allocate(size);
  for (std::size_t i = 0; i < std::size_t(size) * size; ++i)
  {
    map.Radiance[3 * i] = rgb.x;
    map.Radiance[3 * i + 1] = rgb.y;
    map.Radiance[3 * i + 2] = rgb.z;
  }
  map.Finalize();
  return map;
}

EnvironmentMap EnvironmentMap::TwoToneSky(int size, glm::vec3 upper, glm::vec3 lower)
{
  EnvironmentMap map = Allocate(size);
  const int n = size;
  // z > 0 exactly where |u'| + |v'| < 1 (u' = 2u - 1): the horizon is the diamond,
  // and the map is equal-area, so a texel's share of the upper hemisphere is the
  // share of its square inside the diamond.
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      const double x0 = 2.0 * x / n - 1.0, x1 = 2.0 * (x + 1) / n - 1.0;
      const double y0 = 2.0 * y / n - 1.0, y1 = 2.0 * (y + 1) / n - 1.0;
      const double f = SquareInDiamondArea(x0, y0, x1, y1) / ((x1 - x0) * (y1 - y0));
      const glm::vec3 c = glm::vec3(glm::dvec3(upper) * f + glm::dvec3(lower) * (1.0 - f));
      float* out = &map.Radiance[3 * (std::size_t(y) * n + x)];
      out[0] = c.x;
      out[1] = c.y;
      out[2] = c.z;
    }
  }
  map.Finalize();
  return map;
}

EnvironmentMap EnvironmentMap::SunDisk(
  int size, glm::vec3 direction, double angularRadiusDeg, glm::vec3 radiance, glm::vec3 sky)
{
  EnvironmentMap map = Allocate(size);
  const int n = size;
  const double len = glm::length(glm::dvec3(direction));
  if (!(len > 0.0) || !std::isfinite(len))
  {
    throw std::invalid_argument("EnvironmentMap::SunDisk: the sun direction must be a non-zero vector");
  }
  if (!std::isfinite(angularRadiusDeg) || angularRadiusDeg < 0.0)
  {
    throw std::invalid_argument("EnvironmentMap::SunDisk: the angular radius must be >= 0 degrees");
  }
  const glm::dvec3 s = glm::dvec3(direction) / len;
  const double r = std::min(180.0, angularRadiusDeg) * Pi / 180.0;
  std::vector<double> coverage(std::size_t(n) * n, 0.0);
  if (r < 1e-5)
  {
    // Below ~0.0006 degrees: a point light carrying the disk's power, in its texel.
    const glm::uvec2 t = shared::vs_dir_to_texel(glm::vec3(s), unsigned(n));
    const double diskSolidAngle = 2.0 * Pi * (1.0 - std::cos(r));
    coverage[std::size_t(t.y) * n + t.x] = diskSolidAngle / map.TexelSolidAngle();
  }
  else
  {
    std::vector<glm::vec3> corners(std::size_t(n + 1) * (n + 1));
    for (int y = 0; y <= n; ++y)
    {
      for (int x = 0; x <= n; ++x)
      {
        corners[std::size_t(y) * (n + 1) + x] = OctahedralToDirection(double(x) / n, double(y) / n);
      }
    }
    const DiskCoverage disk{ s, r };
    for (int y = 0; y < n; ++y)
    {
      for (int x = 0; x < n; ++x)
      {
        // Quick rejection from the texel centre and corners; refine the rest.
        const glm::dvec3 c(OctahedralToDirection((x + 0.5) / n, (y + 0.5) / n));
        double rho = 0.0;
        for (int k = 0; k < 4; ++k)
        {
          rho = std::max(rho,
            Angle(c, glm::dvec3(corners[std::size_t(y + k / 2) * (n + 1) + x + k % 2])));
        }
        rho = std::min(Pi, 2.0 * rho);
        const double delta = Angle(c, s);
        double f;
        if (delta - rho >= r)
        {
          f = 0.0;
        }
        else if (delta + rho <= r)
        {
          f = 1.0;
        }
        else
        {
          f = disk.Rect(double(x) / n, double(y) / n, double(x + 1) / n, double(y + 1) / n, 0);
        }
        coverage[std::size_t(y) * n + x] = f;
      }
    }
  }
  for (std::size_t i = 0; i < coverage.size(); ++i)
  {
    const glm::vec3 c =
      glm::vec3(glm::dvec3(sky) + (glm::dvec3(radiance) - glm::dvec3(sky)) * coverage[i]);
    map.Radiance[3 * i] = c.x;
    map.Radiance[3 * i + 1] = c.y;
    map.Radiance[3 * i + 2] = c.z;
  }
  map.Finalize();
  return map;
}

} // namespace vs
