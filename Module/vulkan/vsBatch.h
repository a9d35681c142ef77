// vsBatch.h — one command buffer recording many dispatches, separated by
// barriers, submitted once and waited on. Named timers (timestamp query pairs)
// give per-pass device times, summed per name.
//
//   vs::Batch batch(ctx);
//   batch.BeginTimer("sweep");
//   batch.Dispatch(pipeline, set, &push, sizeof(push), groupsX, groupsY, groupsZ);
//   batch.Barrier();
//   batch.EndTimer();
//   batch.Submit();          // waits
//   double s = batch.Seconds("sweep");
#ifndef vsBatch_h
#define vsBatch_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vs
{
class Context;
class ComputePipeline;
class DescriptorSet;

class VISSWEEPCORE_EXPORT Batch
{
public:
  explicit Batch(std::shared_ptr<Context> context, uint32_t maxTimers = 64);
  ~Batch();
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  /** Throws DeviceLimitError when a group count exceeds maxComputeWorkGroupCount. */
  void Dispatch(const ComputePipeline& pipeline, const DescriptorSet& set, const void* push,
    uint32_t pushBytes, uint32_t groupsX, uint32_t groupsY = 1, uint32_t groupsZ = 1);
  /** All earlier shader writes are visible to later shader reads and writes. */
  void Barrier();

  void BeginTimer(const std::string& name);
  void EndTimer();

  /** Ends recording, submits, waits; then the batch can record again. */
  void Submit();

  /** Device seconds of the timers of the last submit, by name (0 when unknown). */
  double Seconds(const std::string& name) const;
  const std::map<std::string, double>& Timings() const { return this->Timings_; }
  uint32_t DispatchCount() const { return this->Dispatches_; }

private:
  void EnsureRecording();

  std::shared_ptr<Context> Context_;
  vk::CommandBuffer Cmd_;
  vk::Fence Fence_;
  vk::QueryPool Queries_;
  uint32_t MaxTimers_ = 0;
  uint32_t UsedQueries_ = 0;
  bool Recording_ = false;
  uint32_t Dispatches_ = 0;
  std::vector<std::string> TimerNames_;
  bool TimerOpen_ = false;
  std::map<std::string, double> Timings_;
};
}

#endif
