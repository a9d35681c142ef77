// vsVisibilityUpdateScheduler.h — lazy visibility updates for animated volumes (von Radziewsky et al. 2017,
// Sec. 9): when only the volume's data changed (a new time step with the same geometry, grid
// parameters, clipping and transfer function), which directions of the visibility grid to
// re-sweep. The grid then mixes directions swept for different time steps; the renderer stays
// unbiased (the grid only shapes the pdf), so staleness costs variance, never correctness.
//   Full              every direction, every time;
//   RoundRobin        the next k directions of the bit-reversed Morton order (update_order.h);
//   EnvironmentGuided k distinct directions drawn from the environment's importance at the
//                     grid's D x D resolution (directions without light are never drawn);
//   Static            every direction at every StaticInterval-th data change, none in between.
// Host-only bookkeeping (no device): the state persists across data changes.
#ifndef vsVisibilityUpdateScheduler_h
#define vsVisibilityUpdateScheduler_h

#include "vissweepCoreModule.h"

#include <cstdint>
#include <vector>

namespace vs
{
enum class UpdateScheme
{
  Full = 0,
  RoundRobin = 1,
  EnvironmentGuided = 2,
  Static = 3
};

struct UpdateSchedule
{
  UpdateScheme Scheme = UpdateScheme::Full;
  uint32_t DirectionsPerFrame = 4; // k of RoundRobin and EnvironmentGuided
  uint32_t StaticInterval = 16;    // data changes between Static's full refreshes
  uint32_t Seed = 1;               // EnvironmentGuided's random numbers
};

class VISSWEEPCORE_EXPORT VisibilityUpdateScheduler
{
public:
  /** The directions (indices n = y * side + x) to re-sweep after a data-only change; empty = none.
   *  `importance`: side * side non-negative weights (row-major texels), used by EnvironmentGuided.
   *  `eligible`: side * side flags, or empty for all; only eligible directions are returned (the
   *  renderer passes the directions it needs, e.g. not those without environment light), and
   *  RoundRobin still returns k of them while any are eligible.
   *  Throws InputError for a side that is not a power of two, or an importance or eligibility of
   *  the wrong size. */
  std::vector<uint32_t> OnDataChange(const UpdateSchedule& schedule, uint32_t side,
    const std::vector<float>& importance, const std::vector<uint8_t>& eligible = {});
  /** A full recompute happened (first grid, new geometry, parameters, clipping or extinction):
   *  Static's interval starts over. */
  void OnFullUpdate() { this->SinceRefresh_ = 0; }

  /** Round-robin counts handed out so far (the position in the update order). */
  uint64_t RoundRobinCount() const { return this->RoundRobinNext_; }

  static std::vector<uint32_t> AllDirections(uint32_t side);

private:
  std::vector<uint32_t> NextRoundRobin(uint32_t side, uint32_t k, const std::vector<uint8_t>& eligible);
  std::vector<uint32_t> DrawFromEnvironment(uint32_t side, uint32_t k, const std::vector<float>& importance, uint32_t seed);

  uint64_t RoundRobinNext_ = 0;
  uint32_t SinceRefresh_ = 0;
  uint32_t Draws_ = 0;
};
}

#endif
