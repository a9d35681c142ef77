// vsVisibilityGridUpdater.h — the visibility grid's update policy: what the grid was computed
// for, which of its directions are still to sweep, and how many to sweep now.
//
// The renderer only samples by the grid (the transmittance of every shadow ray is the true one),
// so any state of the grid gives unbiased samples. That allows two kinds of laziness:
//  - Progressive fill-in. A new grid starts with every direction at visibility 1 (fully
//    visible): there the product pdf of TwoStep is exactly environment sampling. The first
//    Update() after a full invalidation sweeps nothing, so the first frame does not wait for the
//    sweeps; each later Update() sweeps the next directions, brightest environment first, within
//    a time budget (at least one direction per call). Samples of every stage are averaged with
//    equal weights: each is unbiased whatever the grid held when it was drawn, and the grid never
//    depends on the samples, so their mean is unbiased too.
//  - Lazy updates for animated volumes (Sec. 9 of von Radziewsky et al., "Efficient stochastic
//    rendering of static and animated volumes using visibility sweeps", TVCG 2017): after a
//    data-only change, the scheduler's k directions are swept again, the others keep visibility
//    of earlier data.
// Host-side bookkeeping over a vs::VisibilityGrid; no VTK.
#ifndef vsVisibilityGridUpdater_h
#define vsVisibilityGridUpdater_h

#include "vissweepCoreModule.h"
#include "vsVisibilityGrid.h"
#include "vsVisibilityUpdateScheduler.h"

#include <memory>
#include <vector>

namespace vs
{
struct GridUpdateRequest
{
  VisibilityGridParameters Parameters;
  VolumeGeometry Geometry;
  std::vector<glm::dvec4> WorldPlanes;
  /** D x D flags: the directions the renderer reads (empty = all). */
  std::vector<uint8_t> Required;
  /** D x D environment importance at the grid's resolution: the fill-in order (brightest first)
   *  and EnvironmentGuided's weights. Empty = Morton order. */
  std::vector<float> Importance;
  /** The volume's upload count: a new value with nothing else changed is a data-only change. */
  uint64_t DataVersion = 0;
  /** Extinction or geometry changed in a way that is not a data-only change: sweep everything. */
  bool FullUpdate = false;
  /** The grid must hold the current data's visibility in every direction, as a fresh grid would (the
   *  Preview and AmbientOcclusion modes, whose image *is* the grid's light): a data-only change, or
   *  a grid left stale by earlier lazy updates, is then a full invalidation, not a lazy update. */
  bool Exact = false;
  UpdateSchedule Schedule;
  /** Fill a new grid progressively (see above) or sweep every needed direction at once. */
  bool Progressive = true;
  /** Progressive: the device seconds granted to the sweeps by this call. Grants accumulate, and a
   *  direction is swept once they cover its estimated cost (the first direction as soon as the
   *  pooled extinction is built, which measures that cost; a sweep costing more than granted
   *  leaves a debt); 0 = one direction per call. */
  double BudgetSeconds = 0.0;
  /** Sweep pending directions at all (false: only lazy updates after data changes; the grid keeps
   *  visibility 1 where it was never swept). */
  bool FillIn = true;
  /** While a new grid fills in, its required directions not swept yet read, in every cell, the
   *  visibility of the nearest swept direction (FillUnswept) instead of 1: a grid whose swept sun is
   *  shadowed in a cell then does not say the unswept sky beside it is fully visible there. */
  bool FillUnswept = true;
};

struct GridUpdateResult
{
  uint32_t DirectionsSwept = 0;
  double Seconds = 0.0;  // device seconds of this call's sweeps
  bool NewGrid = false;  // a full invalidation: the grid restarted from visibility 1
};

class VISSWEEPCORE_EXPORT VisibilityGridUpdater
{
public:
  explicit VisibilityGridUpdater(std::shared_ptr<Context> context);
  ~VisibilityGridUpdater();

  /** Brings the grid up to date for `request` as far as the policy says. Throws InputError /
   *  DeviceLimitError (nothing is swept then). */
  GridUpdateResult Update(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const GridUpdateRequest& request, const VisibilityGrid::Progress& progress = {});

  /** Sweeps every direction not swept since the last full update (required or not), e.g. before
   *  the grid is handed out as data. Needs a grid (Update() first). */
  GridUpdateResult Complete(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const GridUpdateRequest& request, const VisibilityGrid::Progress& progress = {});

  /** Forget the grid: the next Update() starts over. */
  void Invalidate();

  const VisibilityGrid* Grid() const { return this->Grid_ && this->Grid_->Valid() ? this->Grid_.get() : nullptr; }
  /** Required directions not yet swept since the last full update. */
  uint32_t PendingDirections() const;
  /** Directions swept since the last full update. */
  uint32_t SweptDirections() const;
  /** The fraction of the environment's importance (over the required directions) whose
   *  directions are swept: 1 when the grid is complete. */
  double SweptImportance() const;
  bool IsComplete() const { return this->Grid() && this->PendingDirections() == 0; }
  /** Bumped by every full invalidation (a new grid that starts at visibility 1). */
  uint64_t Generation() const { return this->Generation_; }
  /** Estimated device seconds of one direction's sweep (0 before the first sweep). */
  double SecondsPerDirection() const { return this->SecondsPerDirection_; }
  /** Estimated device seconds of the sweeps still needed to complete the grid: the pooled
   *  extinction's slabs left plus the pending directions at SecondsPerDirection(). A part not
   *  measured yet counts 0 (the first slab and the first direction show what they cost). */
  double PendingSweepSeconds() const;
  const VisibilityUpdateScheduler& Scheduler() const { return this->Scheduler_; }

  /** Fill-in order: the directions of `candidates` by decreasing importance, ties in the
   *  bit-reversed Morton order of update_order.h (well spread over the sphere). */
  static std::vector<uint32_t> FillOrder(
    uint32_t side, const std::vector<uint32_t>& candidates, const std::vector<float>& importance);

  /** For each direction of `targets` not in `swept` (D x D flags), the swept direction nearest to it
   *  on the sphere (texel centres; ties to the lower index): the pairs (target, source). Empty when
   *  nothing is swept. */
  static std::vector<std::pair<uint32_t, uint32_t>> NearestSwept(
    uint32_t side, const std::vector<uint8_t>& swept, const std::vector<uint8_t>& targets);
  /** Redirections of an unswept direction to a swept one since the last full update (FillUnswept):
   *  each fill redirects only the unswept directions whose nearest swept direction changed. */
  uint64_t FilledDirections() const { return this->Filled_; }

private:
  GridUpdateResult Sweep(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const GridUpdateRequest& request, std::vector<uint32_t> directions, const VisibilityGrid::Progress& progress);
  static std::vector<double> Signature(const GridUpdateRequest& request);

  std::shared_ptr<Context> Context_;
  std::unique_ptr<VisibilityGrid> Grid_;
  VisibilityUpdateScheduler Scheduler_;
  std::vector<double> Signature_;
  std::vector<uint8_t> Swept_;    // per direction: swept since the last full update
  std::vector<uint8_t> Required_; // of the last request
  std::vector<float> Importance_; // of the last request
  uint64_t DataVersion_ = 0;
  bool Stale_ = false;            // a lazy update left directions with an earlier data's visibility
  uint64_t Generation_ = 0;
  double SecondsPerDirection_ = 0.0;
  double Allowance_ = 0.0;        // progressive: sweep seconds granted and not yet spent
  uint64_t Filled_ = 0;
  static constexpr uint32_t NoFillSource = 0xffffffffu;
  std::vector<uint32_t> FillSource_; // per unswept direction: the swept one it holds a copy of
};
}

#endif
