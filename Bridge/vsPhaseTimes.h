// vsPhaseTimes.h — named host wall-clock phases of one piece of work, in the order they ran: the
// scene update's (conversion, upload, quads, ranges, table, majorants) and the mapper's last frame
// (scene, environment, grid, pipeline wait, render, display). Where a first frame's time goes
// (issue 39, item 0); `vissweep render --json` reports the first frame's as first_frame_phases.
// Internal to VisSweep (hidden from the wrappers).
#ifndef vsPhaseTimes_h
#define vsPhaseTimes_h

#if !defined(__VTK_WRAP__)
#include "vissweepBridgeModule.h"

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace vs
{
class VISSWEEPBRIDGE_EXPORT PhaseTimes
{
public:
  using Clock = std::chrono::steady_clock;

  void Clear() { this->Phases_.clear(); }
  /** Adds `seconds` to phase `name` (a new phase at the end, or the one of that name). */
  void Add(const std::string& name, double seconds);
  /** Adds the time since `since` to `name` and returns now: consecutive laps split a span. */
  Clock::time_point Lap(const std::string& name, Clock::time_point since);
  /** Each phase of `other` as `prefix` + its name. */
  void Append(const std::string& prefix, const PhaseTimes& other);
  /** The phase's seconds; 0 when there is none of that name. */
  double Seconds(const std::string& name) const;
  const std::vector<std::pair<std::string, double>>& Phases() const { return this->Phases_; }

private:
  std::vector<std::pair<std::string, double>> Phases_;
};
}
#endif

#endif
