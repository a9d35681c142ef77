// vsMonteCarloFrame.h — the parts of a Monte Carlo frame's render parameters that follow from the
// frame's geometry alone: the window depth subsampled to the image (interactive subsampling), the
// camera, and the volume block (box, dimensions, transfer function, majorants, cropping regions and
// the clipping planes in the volume's index space, where the kernel clips; vs::MakeVolumeParams). Split from the mapper's RenderMonteCarlo, which keeps the
// strategy, the accumulators and the samples. Not wrapped.
#ifndef vsMonteCarloFrame_h
#define vsMonteCarloFrame_h

#include "vsFrameGeometry.h"

#include "sampling/mc_params.h"

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
  /** The camera of `view` and the volume block of `geometry` (cropped), the scene's transfer
   *  function, interpolation and majorants, and the world clipping planes `planes`; throws
   *  vs::InputError for a plane that does not fit in float in the volume's index space. */
  static void SetPlacement(shared::VsMonteCarloParams& p, const CameraView& view, const VolumeGeometry& geometry,
    const VolumeScene& scene, const std::vector<glm::dvec4>& planes);
};
}

#endif
