// vsReduceSum.h — sum of a float array on the device (workgroup tree
// reduction, repeated until one value is left).
#ifndef vsReduceSum_h
#define vsReduceSum_h

#include "vissweepCoreModule.h"

#include <memory>
#include <vector>

namespace vs
{
class ComputePipeline;
class Context;

class VISSWEEPCORE_EXPORT ReduceSum
{
public:
  explicit ReduceSum(std::shared_ptr<Context> context);
  ~ReduceSum();
  /** The sum of `values`, computed on the device in one command buffer. */
  double Sum(const std::vector<float>& values);

private:
  std::shared_ptr<Context> Context_;
  std::shared_ptr<ComputePipeline> Pipeline_;
};
}

#endif
