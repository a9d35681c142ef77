#include "vsBuffer.h"
#include "vsContext.h"
#include "vsError.h"

#include <cstring>
#include <functional>

namespace vs
{
namespace
{
std::string MiB(uint64_t bytes)
{
  return std::to_string(bytes / (1024.0 * 1024.0)).substr(0, 8) + " MiB";
}
}

vk::DeviceMemory AllocateMemory(Context& context, const vk::MemoryRequirements& req,
  bool allowHostVisible, bool& hostVisible, const std::string& what)
{
  const uint64_t heap = context.Info().DeviceLocalHeapBytes;
  if (heap && req.size > heap)
  {
    throw DeviceLimitError(what + " needs " + MiB(req.size) + " of device memory, more than the " +
      MiB(heap) + " heap of '" + context.Info().Name + "'");
  }
  int type = -1;
  hostVisible = false;
  if (allowHostVisible)
  {
    type = context.FindMemoryType(req.memoryTypeBits,
      vk::MemoryPropertyFlagBits::eDeviceLocal | vk::MemoryPropertyFlagBits::eHostVisible |
        vk::MemoryPropertyFlagBits::eHostCoherent);
    hostVisible = type >= 0;
  }
  if (type < 0)
  {
    type = context.FindMemoryType(req.memoryTypeBits, vk::MemoryPropertyFlagBits::eDeviceLocal);
  }
  if (type < 0)
  {
    type = context.FindMemoryType(req.memoryTypeBits,
      vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent);
    hostVisible = type >= 0;
  }
  if (type < 0)
  {
    throw DeviceLimitError(what + ": the device has no suitable memory type");
  }
  vk::MemoryAllocateInfo ai;
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = static_cast<uint32_t>(type);
  try
  {
    return context.Device().allocateMemory(ai);
  }
  catch (const vk::SystemError& e)
  {
    throw DeviceLimitError(what + ": allocating " + MiB(req.size) + " failed (" + e.what() +
      "); the device-local heap is " + MiB(heap));
  }
}

void RunOnce(Context& context, const std::function<void(vk::CommandBuffer)>& record)
{
  vk::Device device = context.Device();
  vk::CommandBufferAllocateInfo ai;
  ai.commandPool = context.CommandPool();
  ai.level = vk::CommandBufferLevel::ePrimary;
  ai.commandBufferCount = 1;
  std::lock_guard<std::mutex> lock(context.QueueMutex());
  vk::CommandBuffer cmd = device.allocateCommandBuffers(ai)[0];
  vk::CommandBufferBeginInfo bi;
  bi.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit;
  cmd.begin(bi);
  record(cmd);
  cmd.end();
  vk::Fence fence = device.createFence(vk::FenceCreateInfo());
  vk::SubmitInfo si;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd;
  try
  {
    context.Queue().submit(si, fence);
    (void)device.waitForFences(fence, VK_TRUE, UINT64_MAX);
  }
  catch (...)
  {
    device.destroyFence(fence);
    device.freeCommandBuffers(context.CommandPool(), cmd);
    throw;
  }
  device.destroyFence(fence);
  device.freeCommandBuffers(context.CommandPool(), cmd);
}

Buffer::Buffer(std::shared_ptr<Context> context, uint64_t bytes, const std::string& name)
  : Context_(std::move(context))
  , Name_(name)
  , Bytes_(bytes)
{
  const auto& info = this->Context_->Info();
  if (bytes == 0)
  {
    throw InputError("buffer '" + name + "' of zero bytes");
  }
  if (bytes > info.MaxStorageBufferRange)
  {
    throw DeviceLimitError("buffer '" + name + "' of " + MiB(bytes) +
      " exceeds the device's maxStorageBufferRange of " + MiB(info.MaxStorageBufferRange) + " on '" +
      info.Name + "'");
  }
  vk::Device device = this->Context_->Device();
  vk::BufferCreateInfo ci;
  ci.size = bytes;
  ci.usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer |
    vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst;
  ci.sharingMode = vk::SharingMode::eExclusive;
  this->Buffer_ = device.createBuffer(ci);
  bool hostVisible = false;
  try
  {
    this->Memory_ = AllocateMemory(*this->Context_, device.getBufferMemoryRequirements(this->Buffer_),
      true, hostVisible, "buffer '" + name + "'");
  }
  catch (...)
  {
    device.destroyBuffer(this->Buffer_);
    throw;
  }
  device.bindBufferMemory(this->Buffer_, this->Memory_, 0);
  if (hostVisible)
  {
    this->Mapped_ = device.mapMemory(this->Memory_, 0, VK_WHOLE_SIZE);
  }
}

Buffer::~Buffer()
{
  vk::Device device = this->Context_->Device();
  for (const auto& view : this->Views_)
  {
    device.destroyBufferView(view.second);
  }
  if (this->Mapped_)
  {
    device.unmapMemory(this->Memory_);
  }
  device.destroyBuffer(this->Buffer_);
  device.freeMemory(this->Memory_);
}

vk::BufferView Buffer::TexelView(vk::Format format) const
{
  for (const auto& view : this->Views_)
  {
    if (view.first == format)
    {
      return view.second;
    }
  }
  const uint64_t texelBytes = format == vk::Format::eR32G32B32A32Sfloat ? 16
    : (format == vk::Format::eR32Sfloat || format == vk::Format::eR32Uint) ? 4
                                                                          : 0;
  if (texelBytes == 0)
  {
    throw InputError("buffer '" + this->Name_ + "': unsupported texel format " + vk::to_string(format));
  }
  const auto& info = this->Context_->Info();
  const uint64_t texels = this->Bytes_ / texelBytes;
  if (texels > info.MaxTexelBufferElements)
  {
    throw DeviceLimitError("buffer '" + this->Name_ + "' of " + std::to_string(texels) +
      " texels exceeds the device's maxTexelBufferElements of " + std::to_string(info.MaxTexelBufferElements) +
      " on '" + info.Name + "'");
  }
  vk::BufferViewCreateInfo ci;
  ci.buffer = this->Buffer_;
  ci.format = format;
  ci.offset = 0;
  ci.range = texels * texelBytes;
  vk::BufferView view = this->Context_->Device().createBufferView(ci);
  this->Views_.emplace_back(format, view);
  return view;
}

void Buffer::Upload(const void* data, uint64_t bytes, uint64_t offset)
{
  if (offset + bytes > this->Bytes_)
  {
    throw InputError("upload of " + std::to_string(bytes) + " bytes past the end of buffer '" + this->Name_ + "'");
  }
  if (this->Mapped_)
  {
    std::memcpy(static_cast<char*>(this->Mapped_) + offset, data, bytes);
    return;
  }
  Buffer staging(this->Context_, bytes, this->Name_ + " (staging)");
  if (!staging.Mapped_)
  {
    throw DeviceLimitError("no host-visible memory for staging '" + this->Name_ + "'");
  }
  std::memcpy(staging.Mapped_, data, bytes);
  RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) {
    vk::BufferCopy region{ 0, offset, bytes };
    cmd.copyBuffer(staging.Handle(), this->Buffer_, region);
  });
}

void Buffer::Download(void* data, uint64_t bytes, uint64_t offset) const
{
  if (offset + bytes > this->Bytes_)
  {
    throw InputError("download of " + std::to_string(bytes) + " bytes past the end of buffer '" + this->Name_ + "'");
  }
  if (this->Mapped_)
  {
    std::memcpy(data, static_cast<const char*>(this->Mapped_) + offset, bytes);
    return;
  }
  Buffer staging(this->Context_, bytes, this->Name_ + " (staging)");
  RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) {
    vk::BufferCopy region{ offset, 0, bytes };
    cmd.copyBuffer(this->Buffer_, staging.Handle(), region);
  });
  std::memcpy(data, staging.Mapped_, bytes);
}

void Buffer::Fill(uint32_t value)
{
  RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) { cmd.fillBuffer(this->Buffer_, 0, VK_WHOLE_SIZE, value); });
}
}
