#include "vsBatch.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsPipeline.h"

namespace vs
{
Batch::Batch(std::shared_ptr<Context> context, uint32_t maxTimers)
  : Context_(std::move(context))
  , MaxTimers_(maxTimers)
{
  vk::Device device = this->Context_->Device();
  vk::CommandBufferAllocateInfo ai;
  ai.commandPool = this->Context_->CommandPool();
  ai.level = vk::CommandBufferLevel::ePrimary;
  ai.commandBufferCount = 1;
  {
    std::lock_guard<std::mutex> lock(this->Context_->QueueMutex());
    this->Cmd_ = device.allocateCommandBuffers(ai)[0];
  }
  this->Fence_ = device.createFence(vk::FenceCreateInfo());
  if (this->Context_->Info().Timestamps && maxTimers > 0)
  {
    vk::QueryPoolCreateInfo qci;
    qci.queryType = vk::QueryType::eTimestamp;
    qci.queryCount = 2 * maxTimers;
    this->Queries_ = device.createQueryPool(qci);
  }
}

Batch::~Batch()
{
  vk::Device device = this->Context_->Device();
  if (this->Recording_)
  {
    this->Cmd_.end();
  }
  if (this->Queries_)
  {
    device.destroyQueryPool(this->Queries_);
  }
  device.destroyFence(this->Fence_);
  std::lock_guard<std::mutex> lock(this->Context_->QueueMutex());
  device.freeCommandBuffers(this->Context_->CommandPool(), this->Cmd_);
}

void Batch::EnsureRecording()
{
  if (this->Recording_)
  {
    return;
  }
  this->Cmd_.reset();
  vk::CommandBufferBeginInfo bi;
  bi.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit;
  this->Cmd_.begin(bi);
  if (this->Queries_)
  {
    this->Cmd_.resetQueryPool(this->Queries_, 0, 2 * this->MaxTimers_);
  }
  this->UsedQueries_ = 0;
  this->TimerNames_.clear();
  this->Dispatches_ = 0;
  this->Recording_ = true;
}

void Batch::Dispatch(const ComputePipeline& pipeline, const DescriptorSet& set, const void* push,
  uint32_t pushBytes, uint32_t gx, uint32_t gy, uint32_t gz)
{
  const auto& info = this->Context_->Info();
  if (gx > info.MaxComputeWorkGroupCount[0] || gy > info.MaxComputeWorkGroupCount[1] ||
    gz > info.MaxComputeWorkGroupCount[2])
  {
    throw DeviceLimitError("dispatch of '" + pipeline.Name() + "' with " + std::to_string(gx) + " x " +
      std::to_string(gy) + " x " + std::to_string(gz) + " workgroups exceeds the device's maxComputeWorkGroupCount");
  }
  if (pushBytes != pipeline.PushConstantBytes())
  {
    throw InputError("dispatch of '" + pipeline.Name() + "' with " + std::to_string(pushBytes) +
      " push-constant bytes; the pipeline declares " + std::to_string(pipeline.PushConstantBytes()));
  }
  if (gx == 0 || gy == 0 || gz == 0)
  {
    return;
  }
  this->EnsureRecording();
  this->Cmd_.bindPipeline(vk::PipelineBindPoint::eCompute, pipeline.Handle());
  vk::DescriptorSet ds = set.Handle();
  this->Cmd_.bindDescriptorSets(vk::PipelineBindPoint::eCompute, pipeline.Layout(), 0, ds, {});
  if (pushBytes)
  {
    this->Cmd_.pushConstants(pipeline.Layout(), vk::ShaderStageFlagBits::eCompute, 0, pushBytes, push);
  }
  this->Cmd_.dispatch(gx, gy, gz);
  ++this->Dispatches_;
}

void Batch::Barrier()
{
  this->EnsureRecording();
  vk::MemoryBarrier mb;
  mb.srcAccessMask = vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eTransferWrite;
  mb.dstAccessMask = vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite |
    vk::AccessFlagBits::eTransferRead;
  this->Cmd_.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer,
    vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer, {}, mb, {}, {});
}

void Batch::BeginTimer(const std::string& name)
{
  this->EnsureRecording();
  if (this->TimerOpen_)
  {
    this->EndTimer();
  }
  if (!this->Queries_ || this->UsedQueries_ + 2 > 2 * this->MaxTimers_)
  {
    return;
  }
  this->Cmd_.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, this->Queries_, this->UsedQueries_);
  this->TimerNames_.push_back(name);
  this->TimerOpen_ = true;
}

void Batch::EndTimer()
{
  if (!this->TimerOpen_)
  {
    return;
  }
  this->Cmd_.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, this->Queries_, this->UsedQueries_ + 1);
  this->UsedQueries_ += 2;
  this->TimerOpen_ = false;
}

void Batch::Submit()
{
  this->Timings_.clear();
  if (!this->Recording_)
  {
    return;
  }
  this->EndTimer();
  this->Cmd_.end();
  this->Recording_ = false;
  vk::Device device = this->Context_->Device();
  vk::SubmitInfo si;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &this->Cmd_;
  {
    std::lock_guard<std::mutex> lock(this->Context_->QueueMutex());
    try
    {
      this->Context_->Queue().submit(si, this->Fence_);
    }
    catch (const vk::SystemError& e)
    {
      throw VulkanCallError(std::string("queue submission failed: ") + e.what());
    }
  }
  vk::Result r = device.waitForFences(this->Fence_, VK_TRUE, UINT64_MAX);
  device.resetFences(this->Fence_);
  if (r != vk::Result::eSuccess)
  {
    throw VulkanCallError("waiting for the device failed: " + vk::to_string(r));
  }
  if (this->Queries_ && this->UsedQueries_)
  {
    std::vector<uint64_t> ticks(this->UsedQueries_);
    (void)device.getQueryPoolResults(this->Queries_, 0, this->UsedQueries_, ticks.size() * sizeof(uint64_t),
      ticks.data(), sizeof(uint64_t), vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
    double period = this->Context_->Info().TimestampPeriodNs * 1e-9;
    for (size_t i = 0; i < this->TimerNames_.size(); ++i)
    {
      this->Timings_[this->TimerNames_[i]] += double(ticks[2 * i + 1] - ticks[2 * i]) * period;
    }
  }
}

double Batch::Seconds(const std::string& name) const
{
  auto it = this->Timings_.find(name);
  return it == this->Timings_.end() ? 0.0 : it->second;
}
}
