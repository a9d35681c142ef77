// vsEmptySpaceDistance.h — how far empty space extends around each brick of the majorant grid, so
// that the trackers cross it in one step: for a brick whose majorant is 0, the chessboard (L-inf)
// distance in bricks to the nearest brick whose majorant is not (bricks beyond the grid count as
// empty); 0 for a non-empty brick. A brick at distance k >= 1 is the centre of a cube of
// (2k - 1)^3 bricks that are all empty: a ray inside that brick can jump to the cube's exit,
// since the extinction is 0 on the whole way there (so the estimators draw no random number and
// stay the same bit for bit).
#ifndef vsEmptySpaceDistance_h
#define vsEmptySpaceDistance_h

#include "vissweepCoreModule.h"

#include <array>
#include <cstdint>
#include <vector>

namespace vs
{
/** Per brick (x fastest), from the bricks' majorants: 0 where the majorant is not 0, else the
 *  chessboard distance to the nearest such brick, at most `cap` (also where there is none).
 *  An exact two-pass chamfer transform over the 26-neighbourhood, O(bricks). */
VISSWEEPCORE_EXPORT std::vector<float> EmptySpaceDistance(
  const std::vector<float>& majorants, std::array<uint32_t, 3> bricks, uint32_t cap);
}

#endif
