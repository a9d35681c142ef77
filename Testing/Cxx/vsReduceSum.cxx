#include "vsReduceSum.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsPipeline.h"

#include "vs_spirv_reduce_sum.h"

namespace vs
{
ReduceSum::ReduceSum(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
  this->Pipeline_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_reduce_sum),
    std::vector<BindingType>{ BindingType::StorageBuffer, BindingType::StorageBuffer }, sizeof(uint32_t),
    "reduce-sum");
}

ReduceSum::~ReduceSum() = default;

double ReduceSum::Sum(const std::vector<float>& values)
{
  if (values.empty())
  {
    return 0.0;
  }
  uint32_t n = static_cast<uint32_t>(values.size());
  Buffer a(this->Context_, uint64_t(n) * sizeof(float), "reduce input");
  Buffer b(this->Context_, uint64_t((n + 255) / 256) * sizeof(float), "reduce output");
  a.Upload(values.data(), uint64_t(n) * sizeof(float));
  // Ping-pong: a -> b -> a ... in one command buffer.
  std::vector<std::unique_ptr<DescriptorSet>> sets;
  Batch batch(this->Context_);
  Buffer* src = &a;
  Buffer* dst = &b;
  while (true)
  {
    uint32_t groups = (n + 255) / 256;
    sets.push_back(std::make_unique<DescriptorSet>(*this->Pipeline_));
    sets.back()->Bind(0, *src).Bind(1, *dst);
    batch.Dispatch(*this->Pipeline_, *sets.back(), &n, sizeof(n), groups);
    batch.Barrier();
    n = groups;
    std::swap(src, dst);
    if (n == 1)
    {
      break;
    }
  }
  batch.Submit();
  float result = 0.0f;
  src->Download(&result, sizeof(float));
  return result;
}
}
