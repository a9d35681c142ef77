// vsVolumeParams.h — the volume block every pass reads (sampling/volume_params.h), filled from the
// volume's geometry, its transfer-function table, its majorant grid and the world clipping planes
// that cut its box. One place, so the Monte Carlo kernel, the emission-absorption pass and the
// sweeps see the same box, the same index-space planes and the same table parameters.
#ifndef vsVolumeParams_h
#define vsVolumeParams_h

#include "vissweepCoreModule.h"
#include "sampling/volume_params.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vs
{
struct VolumeGeometry;
class MajorantGrid;
class TransferFunctionTable;

/** The block of `geometry` (its cropped box, dimensions and cropping regions), `tf`'s parameters,
 *  the scalar's `interpolation` (VS_INTERPOLATION_*) and the world planes `worldPlanes` (at most
 *  VS_MAX_CLIP_PLANES, kept where dot(n, x) + w >= 0) moved into the volume's index space:
 *  n.(M x + o) + w = (M^T n).x + (n.o + w). Throws vs::InputError for more planes than the passes
 *  take, or a plane that does not fit in float in index space. `majorants`, if given, adds the
 *  majorant bricks (the Monte Carlo kernel and the sweeps walk them); without, they are 0. */
VISSWEEPCORE_EXPORT shared::VsVolumeParams MakeVolumeParams(const VolumeGeometry& geometry,
  const TransferFunctionTable& tf, uint32_t interpolation, const std::vector<glm::dvec4>& worldPlanes,
  const MajorantGrid* majorants = nullptr);
}

#endif
