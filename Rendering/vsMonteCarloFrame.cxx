// vsMonteCarloFrame.cxx — a Monte Carlo frame's depth and placement
// (see vsMonteCarloFrame.h).
#include "vsMonteCarloFrame.h"

#include "vsError.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeParams.h"
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

void MonteCarloFrame::SetPlacement(shared::VsMonteCarloParams& p, const CameraView& view,
  const VolumeGeometry& geometry, const VolumeScene& scene, const std::vector<glm::dvec4>& planes)
{
  p.camera.invViewProj = view.InvViewProj;
  p.volume = MakeVolumeParams(geometry, scene.TF(), scene.Interpolation(), planes, &scene.Majorants());
}
}
