// vsMonteCarloFrame.cxx — a Monte Carlo frame's depth, placement and index-space clipping planes
// (see vsMonteCarloFrame.h).
#include "vsMonteCarloFrame.h"

#include "vsError.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeScene.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vs
{
std::vector<float> MonteCarloFrame::SubsampledDepth(
  const std::vector<float>& fullDepth, const Viewport& vp, uint32_t w, uint32_t h, int sub)
{
  std::vector<float> depth(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      depth[size_t(y) * w + x] = fullDepth[size_t(std::min<uint32_t>(y * sub, vp.Height - 1)) * vp.Width +
        std::min<uint32_t>(x * sub, vp.Width - 1)];
  return depth;
}

void MonteCarloFrame::SetPlacement(
  shared::VsRenderParams& p, const CameraView& view, const VolumeGeometry& geometry, const VolumeScene& scene)
{
  p.invViewProj = view.InvViewProj;
  p.worldToIndex = glm::mat4(geometry.WorldToIndex);
  p.boxMin = glm::vec4(geometry.BoxMin, 0.0f);
  p.boxMax = glm::vec4(geometry.BoxMax, 0.0f);
  p.dims = glm::vec4(geometry.Dims[0], geometry.Dims[1], geometry.Dims[2], 0.0f);
  auto tf = scene.TF().Params();
  p.tf = glm::vec4(tf[0], tf[1], tf[2], tf[3]);
}

void MonteCarloFrame::SetIndexPlanes(
  shared::VsRenderParams& p, const std::vector<glm::dvec4>& planes, const VolumeGeometry& geometry)
{
  const glm::dmat3 m(geometry.IndexToWorld);
  const glm::dvec3 o(geometry.IndexToWorld[3]);
  for (size_t i = 0; i < planes.size(); ++i)
  {
    glm::dvec3 n(planes[i]);
    p.clipPlanes[i] = glm::vec4(glm::vec3(glm::transpose(m) * n), float(glm::dot(n, o) + planes[i].w));
    const glm::vec4& c = p.clipPlanes[i];
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w)))
    {
      throw vs::InputError("clipping plane " + std::to_string(i) + " does not fit in float in the volume's index space");
    }
  }
}
}
