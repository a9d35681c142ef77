#include "vsAccumulationSignature.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace vs
{
// Equal up to rounding: VTK recomputes the camera matrices on some passes (e.g. while
// vtkWindowToImageFilter grabs the window) with last-bit differences that are no change.
bool AccumulationSignature::NearlyEqual(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (std::abs(a[i] - b[i]) > 1e-6 * std::max({ 1.0, std::abs(a[i]), std::abs(b[i]) }))
    {
      return false;
    }
  }
  return true;
}

// Every value of the render parameters, integers by value: reinterpreting them as floats
// made small integers (the strategy, the cell mode) denormals that NearlyEqual took for 0,
// so switching Uniform -> Environment kept accumulating into the old image.
std::vector<double> AccumulationSignature::Of(const vs::shared::VsRenderParams& p)
{
  // Not in the signature: directionSources, which MonteCarloPass sets from the grid as it fills in
  // (samples of every stage of the grid are averaged; VisibilityGridUpdater).
  static_assert(sizeof(vs::shared::VsRenderParams) ==
      2 * 64 + (16 + vs::shared::VS_MAX_CLIP_PLANES) * 16 + vs::shared::VS_MAX_RENDER_DIRECTIONS * 4,
    "a member was added to VsRenderParams: add it to the signature");
  std::vector<double> s;
  auto addMat = [&s](const glm::mat4& m) { s.insert(s.end(), &m[0][0], &m[0][0] + 16); };
  auto addVec = [&s](const glm::vec4& v) { s.insert(s.end(), { v.x, v.y, v.z, v.w }); };
  auto addUint = [&s](const glm::uvec4& v) { s.insert(s.end(), { double(v.x), double(v.y), double(v.z), double(v.w) }); };
  addMat(p.invViewProj);
  addMat(p.worldToIndex);
  for (const auto& v : { p.boxMin, p.boxMax, p.dims, p.tf, p.background, p.sampling2, p.cellSize, p.tracking, p.cropLo,
         p.cropHi, p.mixture })
  {
    addVec(v);
  }
  for (const auto& v : { p.viewport, p.sampling, p.grid, p.bricks, p.crop })
  {
    addUint(v);
  }
  for (const auto& v : p.clipPlanes)
  {
    addVec(v);
  }
  return s;
}
}
