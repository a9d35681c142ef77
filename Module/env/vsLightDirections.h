// vsLightDirections.h — where the light of each direction texel comes from: for each of the
// D x D equal-area octahedral texels of the visibility grid, the environment's luminance-weighted
// mean direction inside it (the texel centre where the texel is black). The renderer sweeps the
// grid along these directions, so the visibility of a texel holding a sun is the visibility of
// the sun itself, not of the texel's centre up to half a texel (about 11 degrees at 8 x 8) away.
// The grid only shapes the sampling pdf, so any choice of directions keeps the renderer unbiased.
#ifndef vsLightDirections_h
#define vsLightDirections_h

#include "vissweepCoreModule.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vs
{
class EnvironmentMap;

/** D x D unit world directions (row-major texels). Throws InputError unless D is a power of two
 *  no larger than the map. */
VISSWEEPCORE_EXPORT std::vector<glm::vec3> LightWeightedDirections(const EnvironmentMap& map, uint32_t side);
}

#endif
