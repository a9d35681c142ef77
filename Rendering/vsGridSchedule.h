// vsGridSchedule.h — what a frame asks of the visibility grid: the grid's parameters from the
// mapper's settings, the directions the sampling strategy reads (all, or only the lit ones), and
// the whole vs::GridUpdateRequest (placement, clipping planes, importance, data version, schedule,
// sweep budget) that vs::VisibilityGridUpdater carries out. Split from the mapper's
// UpdateVisibilityGrid; the mapper still runs the update and counts the sweeps. Not wrapped.
#ifndef vsGridSchedule_h
#define vsGridSchedule_h

#include "vsVisibilityGridUpdater.h"

#include <cstdint>
#include <vector>

class vtkVisibilitySweepVolumeMapper;

namespace vs
{
class MapperEnvironment;
class StrategySelector;
class VolumeScene;

class GridSchedule
{
public:
  /** The grid's parameters from the mapper's settings. */
  static VisibilityGridParameters Parameters(int directionResolution, double voxelsPerCell, int kernelResolution,
    bool filtering, double filterAngleFraction);
  /** The directions (side x side) this render needs swept: 1 to sweep, 0 to leave out. */
  static std::vector<uint8_t> RequiredDirections(vtkVisibilitySweepVolumeMapper* mapper, MapperEnvironment& environment,
    int side);
  /** Fills `r` with what the frame needs of the grid of `geometry`. pendingSweepSeconds: the
   *  estimated device seconds of the sweeps the grid still needs (VisibilityGridUpdater::
   *  PendingSweepSeconds; 0 without a grid yet). */
  static void FillRequest(vtkVisibilitySweepVolumeMapper* mapper, GridUpdateRequest& r, const VolumeGeometry& geometry,
    MapperEnvironment& environment, VolumeScene& scene, bool fullUpdate, StrategySelector& selector,
    double lastRenderSeconds, bool autoStrategy, double pendingSweepSeconds);
  /** Whether Auto fills its grid in this frame: not while TwoStep, judged on its grid, loses
   *  (StrategySelector::GridWorthSweeping), nor while the sweeps still pending cost more than they
   *  can pay back before the mapper's RemainingTimeBudget (StrategySelector::AffordableSweepSeconds
   *  at the frame's sweep fraction). */
  static bool AutoFillsIn(const StrategySelector& selector, double sweepFraction, double remainingSeconds,
    double pendingSweepSeconds);
};
}

#endif
