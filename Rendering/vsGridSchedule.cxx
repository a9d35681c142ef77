// vsGridSchedule.cxx — the visibility grid's request for a frame (see vsGridSchedule.h).
#include "vsGridSchedule.h"

#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsFrameGeometry.h"
#include "vsMapperEnvironment.h"
#include "vsStrategySelector.h"
#include "vsSweepPlan.h"
#include "vsVolumeScene.h"
#include "sampling/interpolation.h"
#include "sampling/update_order.h"

#include <algorithm>
#include <cmath>

namespace vs
{
VisibilityGridParameters GridSchedule::Parameters(int directionResolution, double voxelsPerCell, int kernelResolution,
  bool filtering, double filterAngleFraction)
{
  vs::VisibilityGridParameters gp;
  gp.DirectionResolution = uint32_t(std::max(0, directionResolution));
  gp.VoxelsPerCell = voxelsPerCell;
  gp.KernelResolution = uint32_t(kernelResolution);
  gp.AutoKernelRaysPerCell = vs::RendererKernelRaysPerCell; // the renderer only samples by the grid
  gp.Filtering = filtering;
  gp.FilterAngleFraction = filterAngleFraction;
  return gp;
}

// The directions this render needs swept: all of them, except that Combined and TwoStep never
// read the visibility of a direction whose environment importance at the grid's resolution is 0
// (their product weight is visibility x importance), so with SkipUnlitDirections those are left
// out (the README's skip rules: directions without environment radiance never need sweeping).
std::vector<uint8_t> GridSchedule::RequiredDirections(vtkVisibilitySweepVolumeMapper* mapper,
  MapperEnvironment& environment, int side)
{
  std::vector<uint8_t> required(size_t(side) * side, 1);
  if (mapper->GetSkipUnlitDirections() &&
    (mapper->GetSamplingStrategy() == vtkVisibilitySweepVolumeMapper::Combined ||
      mapper->GetSamplingStrategy() == vtkVisibilitySweepVolumeMapper::TwoStep))
  {
    const std::vector<float> importance = environment.Device().ImportanceLevel(int(vs::shared::vs_log2_pow2(uint32_t(side))));
    for (size_t n = 0; n < required.size() && n < importance.size(); ++n)
    {
      required[n] = importance[n] > 0.0f;
    }
  }
  return required;
}

// The grid's update policy lives in vs::VisibilityGridUpdater; the mapper says what the frame needs:
// the grid's parameters and placement, the directions read (RequiredDirections), the environment's
// importance (the fill-in order), the data version (lazy updates) and the sweep budget.
void GridSchedule::FillRequest(vtkVisibilitySweepVolumeMapper* mapper, GridUpdateRequest& r,
  const VolumeGeometry& geometry, MapperEnvironment& environment, VolumeScene& scene, bool fullUpdate,
  StrategySelector& selector, double lastRenderSeconds, bool autoStrategy, double remainingSeconds,
  double pendingSweepSeconds)
{
  r.Parameters = Parameters(mapper->GetDirectionResolution(),
    mapper->GetVoxelsPerCell() > 0.0 ? std::max(1.0, mapper->GetVoxelsPerCell()) : vs::SweepPlan::AutomaticVoxelsPerCell(geometry),
    mapper->GetKernelResolution(), mapper->GetFiltering(), mapper->GetFilterAngleFraction());
  r.Parameters.NearestInterpolation = scene.Interpolation() == vs::shared::VS_INTERPOLATION_NEAREST;
  r.Parameters.ExtinctionPooling = uint32_t(mapper->GetExtinctionPooling());
  r.Geometry = geometry;
  r.WorldPlanes = vs::FrameGeometry::WorldPlanes(mapper->GetClippingPlanes(), geometry);
  const int side = int(r.Parameters.DirectionResolution);
  if (mapper->GetLightWeightedDirections() && environment.HasLightDirections(side))
  {
    r.Parameters.Directions = environment.LightDirections(mapper->GetEnvironmentUploadCount(), side);
  }
  r.Required = RequiredDirections(mapper, environment, side);
  r.Importance = environment.Device().ImportanceLevel(int(vs::shared::vs_log2_pow2(uint32_t(side))));
  r.DataVersion = uint64_t(scene.Uploads());
  r.FullUpdate = fullUpdate;
  // The Preview and AmbientOcclusion modes show the grid's light itself: no lazy update may leave it
  // stale (the Monte Carlo estimate is unbiased whatever the grid holds, these images are not).
  r.Exact = mapper->GetRenderMode() == vtkVisibilitySweepVolumeMapper::Preview ||
    mapper->GetRenderMode() == vtkVisibilitySweepVolumeMapper::AmbientOcclusion;
  r.Schedule.Scheme = vs::UpdateScheme(mapper->GetUpdateScheme());
  r.Schedule.DirectionsPerFrame = uint32_t(mapper->GetDirectionsPerFrame());
  r.Schedule.StaticInterval = uint32_t(mapper->GetStaticInterval());
  r.Schedule.Seed = uint32_t(mapper->GetSeed());
  r.Progressive = mapper->GetProgressiveVisibility();
  // Auto invests in the grid in proportion to what TwoStep has shown it gains (StrategySelector::SweepFraction).
  const double fraction = autoStrategy
    ? selector.SweepFraction(std::min(mapper->GetSweepFrameFraction(), mapper->GetAutoProbeFraction()), mapper->GetSweepFrameFraction())
    : mapper->GetSweepFrameFraction();
  r.BudgetSeconds = fraction * lastRenderSeconds;
  // Auto stops filling in when the sweeps cannot pay (AutoFillsIn); lazy updates and invalidations
  // still happen.
  r.FillIn = !autoStrategy || AutoFillsIn(selector, fraction, remainingSeconds, pendingSweepSeconds);
  r.FillUnswept = mapper->GetFillUnsweptDirections();
}

double GridSchedule::RemainingSeconds(
  double deadline, int maximumSamples, int accumulatedSamples, double secondsPerSample)
{
  const bool hasDeadline = deadline > 0.0 && std::isfinite(deadline);
  double remaining = hasDeadline ? deadline : 0.0;
  if (secondsPerSample > 0.0 && std::isfinite(secondsPerSample))
  {
    const double toTarget = std::max(1e-3, double(maximumSamples - accumulatedSamples) * secondsPerSample);
    remaining = hasDeadline ? std::min(remaining, toTarget) : toTarget;
  }
  return remaining;
}

bool GridSchedule::AutoFillsIn(const StrategySelector& selector, double sweepFraction, double remainingSeconds,
  double pendingSweepSeconds)
{
  // TwoStep, measured with half of the light's directions swept, loses to Environment sampling at
  // equal time.
  if (!selector.GridWorthSweeping())
  {
    return false;
  }
  // Issue 39: at 2-6 s on the 0.5 mm MRI Auto swept 3-8% of the time (the pooled extinction of 35 M
  // voxels, 0.3-0.5 s in all, then 64 directions) towards a grid that the budget ended before. A part
  // not measured yet counts 0, so the first slab and the first direction are swept to learn their
  // cost.
  return pendingSweepSeconds <=
    StrategySelector::AffordableSweepSeconds(remainingSeconds, sweepFraction, selector.ExpectedGridEfficiency());
}
}
