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
  /** Fills `r` with what the frame needs of the grid of `geometry`. remainingSeconds: the render's
   *  horizon (RemainingSeconds; <= 0: none). pendingSweepSeconds: the estimated device seconds of the
   *  sweeps the grid still needs (VisibilityGridUpdater::PendingSweepSeconds; 0 without a grid yet). */
  static void FillRequest(vtkVisibilitySweepVolumeMapper* mapper, GridUpdateRequest& r, const VolumeGeometry& geometry,
    MapperEnvironment& environment, VolumeScene& scene, bool fullUpdate, StrategySelector& selector,
    double lastRenderSeconds, bool autoStrategy, double remainingSeconds, double pendingSweepSeconds);
  /** The seconds a render has left, for Auto's sweeps: the nearer of the deadline (the mapper's
   *  RemainingTimeBudget, <= 0: none) and the time the samples left to maximumSamples take at
   *  secondsPerSample (the last frame's device seconds per sample; <= 0: unknown). A render that has
   *  its samples has 1 ms left; 0 when neither is known (no horizon). A sample target is a deadline
   *  too: `vissweep render --spp 32` of the key-lit MRI took Auto 0.97-1.31x Environment sampling's time (5 runs),
   *  sweeping a grid its 32 samples could not repay. */
  static double RemainingSeconds(double deadline, int maximumSamples, int accumulatedSamples, double secondsPerSample);
  /** Whether Auto fills its grid in this frame: not while TwoStep, judged on its grid, loses
   *  (StrategySelector::GridWorthSweeping), nor while the sweeps still pending cost more than they
   *  can pay back in the render's remainingSeconds (RemainingSeconds; StrategySelector::
   *  AffordableSweepSeconds at the frame's sweep fraction). */
  static bool AutoFillsIn(const StrategySelector& selector, double sweepFraction, double remainingSeconds,
    double pendingSweepSeconds);
};
}

#endif
