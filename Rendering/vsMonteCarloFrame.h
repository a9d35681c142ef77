// vsMonteCarloFrame.h — the parts of a Monte Carlo frame's render parameters that follow from the
// frame's geometry alone: the window depth subsampled to the image (interactive subsampling), the
// camera, box, dimensions and transfer function, and the clipping planes moved into the volume's
// index space (where the kernel clips). Split from the mapper's RenderMonteCarlo, which keeps the
// strategy, the accumulators and the samples. Not wrapped.
#ifndef vsMonteCarloFrame_h
#define vsMonteCarloFrame_h

#include "vsFrameGeometry.h"

#include "sampling/render_params.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vs
{
class VolumeScene;

class MonteCarloFrame
{
public:
  /** The w x h image's depth: the pixel of the viewport's `fullDepth` (rows bottom-up) at each
   *  subsampled pixel's corner, clamped to the viewport. */
  static std::vector<float> SubsampledDepth(
    const std::vector<float>& fullDepth, const Viewport& vp, uint32_t w, uint32_t h, int sub);
  /** The camera of `view`, the (cropped) box and dimensions of `geometry` and the scene's transfer function. */
  static void SetPlacement(
    shared::VsRenderParams& p, const CameraView& view, const VolumeGeometry& geometry, const VolumeScene& scene);
  /** The world planes `planes` in the index space of `geometry`; throws vs::InputError for a plane
   *  that does not fit in float there. */
  static void SetIndexPlanes(
    shared::VsRenderParams& p, const std::vector<glm::dvec4>& planes, const VolumeGeometry& geometry);
};
}

#endif
