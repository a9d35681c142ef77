#include "vsStagedUpload.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsImage.h"

#include <algorithm>
#include <mutex>

namespace vs
{
struct StagedUpload::Slot
{
  std::unique_ptr<Buffer> Staging;
  std::vector<char> Host; // when the staging memory is not host-visible
  vk::CommandBuffer Command;
  vk::Fence Fence;
  bool InFlight = false;
};

uint32_t StagedUpload::SlicesPerChunk(const std::vector<Image3D*>& images, uint64_t bytes)
{
  uint64_t slice = 0;
  for (const Image3D* image : images)
  {
    slice += uint64_t(image->Width()) * image->Height() * Image3D::TexelBytes(image->Format());
  }
  return uint32_t(std::max<uint64_t>(1, slice ? bytes / slice : 1));
}

StagedUpload::StagedUpload(
  std::shared_ptr<Context> context, std::vector<Image3D*> images, uint32_t slicesPerChunk, uint32_t ring)
  : Context_(std::move(context))
  , Images_(std::move(images))
  , SlicesPerChunk_(std::max(1u, slicesPerChunk))
{
  if (this->Images_.empty())
  {
    throw InputError("a staged upload needs at least one image");
  }
  for (const Image3D* image : this->Images_)
  {
    if (image->Width() != this->Images_[0]->Width() || image->Height() != this->Images_[0]->Height())
    {
      throw InputError("the images of a staged upload differ in width or height");
    }
  }
  this->SliceTexels_ = uint64_t(this->Images_[0]->Width()) * this->Images_[0]->Height();
  uint64_t chunkBytes = 0;
  for (const Image3D* image : this->Images_)
  {
    chunkBytes += this->SliceTexels_ * Image3D::TexelBytes(image->Format()) * this->SlicesPerChunk_;
  }
  vk::Device device = this->Context_->Device();
  vk::CommandPoolCreateInfo pci;
  pci.flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer | vk::CommandPoolCreateFlagBits::eTransient;
  pci.queueFamilyIndex = this->Context_->QueueFamily();
  this->Pool_ = device.createCommandPool(pci);
  try
  {
    vk::CommandBufferAllocateInfo ai;
    ai.commandPool = this->Pool_;
    ai.level = vk::CommandBufferLevel::ePrimary;
    ai.commandBufferCount = std::max(1u, ring);
    const std::vector<vk::CommandBuffer> commands = device.allocateCommandBuffers(ai);
    for (vk::CommandBuffer command : commands)
    {
      auto slot = std::make_unique<Slot>();
      slot->Command = command;
      slot->Fence = device.createFence(vk::FenceCreateInfo());
      this->Slots_.push_back(std::move(slot));
      this->Slots_.back()->Staging =
        std::make_unique<Buffer>(this->Context_, chunkBytes, this->Images_[0]->Name() + " (staging)");
      if (!this->Slots_.back()->Staging->Mapped())
      {
        this->Slots_.back()->Host.resize(chunkBytes);
      }
    }
  }
  catch (...)
  {
    for (auto& slot : this->Slots_)
    {
      device.destroyFence(slot->Fence);
    }
    this->Slots_.clear();
    device.destroyCommandPool(this->Pool_);
    throw;
  }
}

StagedUpload::~StagedUpload()
{
  vk::Device device = this->Context_->Device();
  for (auto& slot : this->Slots_)
  {
    if (slot->InFlight)
    {
      (void)device.waitForFences(slot->Fence, VK_TRUE, UINT64_MAX);
    }
    device.destroyFence(slot->Fence);
    slot->Staging.reset();
  }
  device.destroyCommandPool(this->Pool_); // frees the command buffers
}

void StagedUpload::Wait(Slot& slot)
{
  if (slot.InFlight)
  {
    vk::Device device = this->Context_->Device();
    (void)device.waitForFences(slot.Fence, VK_TRUE, UINT64_MAX);
    device.resetFences(slot.Fence);
    slot.InFlight = false;
  }
}

void StagedUpload::Begin(uint32_t z0, uint32_t count)
{
  if (count == 0 || count > this->SlicesPerChunk_)
  {
    throw InputError("a staged upload's chunk of " + std::to_string(count) + " slices (at most " +
      std::to_string(this->SlicesPerChunk_) + ")");
  }
  for (const Image3D* image : this->Images_)
  {
    if (uint64_t(z0) + count > image->Depth())
    {
      throw InputError("upload past the last slice of image '" + image->Name() + "'");
    }
  }
  this->Current_ = this->Slots_[this->Next_].get();
  this->Next_ = (this->Next_ + 1) % this->Slots_.size();
  this->Wait(*this->Current_);
  this->Z0_ = z0;
  this->Count_ = count;
}

void* StagedUpload::Texels(size_t image)
{
  if (!this->Current_ || image >= this->Images_.size())
  {
    throw InputError("a staged upload's texels outside a chunk or of no image");
  }
  uint64_t offset = 0;
  for (size_t i = 0; i < image; ++i)
  {
    offset += this->SliceTexels_ * Image3D::TexelBytes(this->Images_[i]->Format()) * this->SlicesPerChunk_;
  }
  char* base = this->Current_->Host.empty() ? static_cast<char*>(this->Current_->Staging->Mapped())
                                             : this->Current_->Host.data();
  return base + offset;
}

void StagedUpload::Submit()
{
  if (!this->Current_)
  {
    throw InputError("a staged upload's Submit without Begin");
  }
  Slot& slot = *this->Current_;
  this->Current_ = nullptr;
  if (!slot.Host.empty())
  {
    slot.Staging->Upload(slot.Host.data(), slot.Host.size());
  }
  vk::CommandBuffer cmd = slot.Command;
  cmd.reset();
  vk::CommandBufferBeginInfo bi;
  bi.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit;
  cmd.begin(bi);
  // Each chunk's command buffer moves the images to TRANSFER_DST_OPTIMAL and back to GENERAL (their
  // resting layout, for the shaders), so chunks of several threads may follow each other in any order.
  auto barriers = [&](vk::ImageLayout from, vk::ImageLayout to, vk::AccessFlags src, vk::AccessFlags dst) {
    std::vector<vk::ImageMemoryBarrier> list;
    for (const Image3D* image : this->Images_)
    {
      vk::ImageMemoryBarrier b;
      b.srcAccessMask = src;
      b.dstAccessMask = dst;
      b.oldLayout = from;
      b.newLayout = to;
      b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      b.image = image->Handle();
      b.subresourceRange = vk::ImageSubresourceRange{ vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1 };
      list.push_back(b);
    }
    return list;
  };
  const vk::AccessFlags any = vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite |
    vk::AccessFlagBits::eTransferRead | vk::AccessFlagBits::eTransferWrite;
  const vk::PipelineStageFlags stages = vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer;
  cmd.pipelineBarrier(stages, vk::PipelineStageFlagBits::eTransfer, {}, {}, {},
    barriers(vk::ImageLayout::eGeneral, vk::ImageLayout::eTransferDstOptimal, any, vk::AccessFlagBits::eTransferWrite));
  uint64_t offset = 0;
  for (const Image3D* image : this->Images_)
  {
    vk::BufferImageCopy region;
    region.bufferOffset = offset;
    region.imageSubresource = vk::ImageSubresourceLayers{ vk::ImageAspectFlagBits::eColor, 0, 0, 1 };
    region.imageOffset = vk::Offset3D{ 0, 0, int32_t(this->Z0_) };
    region.imageExtent = vk::Extent3D{ image->Width(), image->Height(), this->Count_ };
    cmd.copyBufferToImage(slot.Staging->Handle(), image->Handle(), vk::ImageLayout::eTransferDstOptimal, region);
    offset += this->SliceTexels_ * Image3D::TexelBytes(image->Format()) * this->SlicesPerChunk_;
  }
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, stages, {}, {}, {},
    barriers(vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eGeneral, vk::AccessFlagBits::eTransferWrite, any));
  cmd.end();
  vk::SubmitInfo si;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd;
  {
    std::lock_guard<std::mutex> lock(this->Context_->QueueMutex());
    this->Context_->Queue().submit(si, slot.Fence);
  }
  slot.InFlight = true;
}

void StagedUpload::Finish()
{
  for (auto& slot : this->Slots_)
  {
    this->Wait(*slot);
  }
}
}
