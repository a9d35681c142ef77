#include "vsImage.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsError.h"

#include <sstream>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vs
{
namespace
{
const vk::ImageUsageFlags kUsage = vk::ImageUsageFlagBits::eStorage |
  vk::ImageUsageFlagBits::eTransferSrc | vk::ImageUsageFlagBits::eTransferDst;

// Moves the image between GENERAL (its resting layout, for the shaders) and a transfer layout.
void Transition(vk::CommandBuffer cmd, vk::Image image, vk::ImageLayout from, vk::ImageLayout to)
{
  vk::ImageMemoryBarrier b;
  b.srcAccessMask = vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eTransferWrite;
  b.dstAccessMask = vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite |
    vk::AccessFlagBits::eTransferRead | vk::AccessFlagBits::eTransferWrite;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = vk::ImageSubresourceRange{ vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1 };
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer,
    vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer, {}, {}, {}, b);
}

// On a device whose image memory the host can map (lavapipe: the CPU's own memory), asks the kernel for
// transparent huge pages over a large image's memory before anything touches it (Linux, THP in
// "madvise" mode as on Debian 12). Issue 39: the first writes into ch2better's 282 MB of images (the
// upload's copies) took one page fault per 4 KB, most of the upload's time in a trace; 2 MB pages
// fault 512x less. Only a hint: nothing changes where the kernel or the driver declines it.
void AdviseHugePages(Context& context, vk::DeviceMemory memory, uint64_t bytes, uint32_t type)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const uint64_t huge = 2ull << 20;
  if (bytes < 4 * huge)
  {
    return;
  }
  const auto props = context.Physical().getMemoryProperties();
  if (type >= props.memoryTypeCount ||
    !(props.memoryTypes[type].propertyFlags & vk::MemoryPropertyFlagBits::eHostVisible))
  {
    return;
  }
  void* mapped = nullptr;
  try
  {
    mapped = context.Device().mapMemory(memory, 0, VK_WHOLE_SIZE);
  }
  catch (const vk::SystemError&)
  {
    return;
  }
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(mapped) + huge - 1) & ~uintptr_t(huge - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(mapped) + bytes) & ~uintptr_t(huge - 1);
  if (end > begin)
  {
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
  context.Device().unmapMemory(memory);
#else
  (void)context;
  (void)memory;
  (void)bytes;
  (void)type;
#endif
}

std::string Extent(uint32_t w, uint32_t h, uint32_t d)
{
  std::ostringstream os;
  os << w << " x " << h << " x " << d;
  return os.str();
}
}

uint32_t Image3D::TexelBytes(vk::Format format)
{
  switch (format)
  {
    case vk::Format::eR8Unorm:
      return 1;
    case vk::Format::eR16Unorm:
    case vk::Format::eR16Sfloat:
      return 2;
    case vk::Format::eR32Sfloat:
    case vk::Format::eR32Uint:
      return 4;
    case vk::Format::eR32G32B32A32Sfloat:
      return 16;
    default:
      throw InputError("unsupported image format " + vk::to_string(format));
  }
}

void Image3D::CheckLimits(Context& context, uint32_t width, uint32_t height, uint32_t depth,
  vk::Format format, const std::string& name)
{
  const auto& info = context.Info();
  if (width == 0 || height == 0 || depth == 0)
  {
    throw InputError("image '" + name + "' has an empty extent " + Extent(width, height, depth));
  }
  uint32_t largest = std::max(width, std::max(height, depth));
  if (largest > info.MaxImageDimension3D)
  {
    throw DeviceLimitError("image '" + name + "' of " + Extent(width, height, depth) +
      " exceeds the device's maxImageDimension3D of " + std::to_string(info.MaxImageDimension3D) +
      " on '" + info.Name + "'");
  }
  vk::ImageFormatProperties props;
  try
  {
    props = context.Physical().getImageFormatProperties(
      format, vk::ImageType::e3D, vk::ImageTiling::eOptimal, kUsage);
  }
  catch (const vk::SystemError&)
  {
    throw DeviceLimitError("image '" + name + "': format " + vk::to_string(format) +
      " is not supported as a 3D storage image on '" + info.Name + "'");
  }
  uint64_t bytes = uint64_t(width) * height * depth * TexelBytes(format);
  if (bytes > props.maxResourceSize)
  {
    throw DeviceLimitError("image '" + name + "' of " + Extent(width, height, depth) + " (" +
      std::to_string(bytes >> 20) + " MiB) exceeds the device's maxResourceSize of " +
      std::to_string(props.maxResourceSize >> 20) + " MiB");
  }
  if (info.DeviceLocalHeapBytes && bytes > info.DeviceLocalHeapBytes)
  {
    throw DeviceLimitError("image '" + name + "' of " + Extent(width, height, depth) + " needs " +
      std::to_string(bytes >> 20) + " MiB, more than the device-local heap of " +
      std::to_string(info.DeviceLocalHeapBytes >> 20) + " MiB");
  }
}

Image3D::Image3D(std::shared_ptr<Context> context, uint32_t width, uint32_t height, uint32_t depth,
  vk::Format format, const std::string& name)
  : Context_(std::move(context))
  , Name_(name)
  , Extent_{ width, height, depth }
  , Format_(format)
{
  CheckLimits(*this->Context_, width, height, depth, format, name);
  vk::Device device = this->Context_->Device();
  vk::ImageCreateInfo ci;
  ci.imageType = vk::ImageType::e3D;
  ci.format = format;
  ci.extent = vk::Extent3D{ width, height, depth };
  ci.mipLevels = 1;
  ci.arrayLayers = 1;
  ci.samples = vk::SampleCountFlagBits::e1;
  ci.tiling = vk::ImageTiling::eOptimal;
  ci.usage = kUsage;
  ci.sharingMode = vk::SharingMode::eExclusive;
  ci.initialLayout = vk::ImageLayout::eUndefined;
  this->Image_ = device.createImage(ci);
  bool hostVisible = false;
  const vk::MemoryRequirements requirements = device.getImageMemoryRequirements(this->Image_);
  try
  {
    this->Memory_ = AllocateMemory(*this->Context_, requirements, false, hostVisible, "image '" + name + "'");
  }
  catch (...)
  {
    device.destroyImage(this->Image_);
    throw;
  }
  device.bindImageMemory(this->Image_, this->Memory_, 0);
  this->MemoryBytes_ = requirements.size;
  const int type = this->Context_->FindMemoryType(requirements.memoryTypeBits, vk::MemoryPropertyFlagBits::eDeviceLocal);
  AdviseHugePages(*this->Context_, this->Memory_, requirements.size, uint32_t(type));
  // The memory the allocation took (AllocateMemory: the first device-local type) is the host's own
  // on a CPU device: MapHostMemory lets the upload fault it in on the host's threads.
  const auto memoryProps = this->Context_->Physical().getMemoryProperties();
  this->HostMemoryType_ = type >= 0 && uint32_t(type) < memoryProps.memoryTypeCount &&
    (memoryProps.memoryTypes[uint32_t(type)].propertyFlags & vk::MemoryPropertyFlagBits::eHostVisible) &&
    this->Context_->Physical().getProperties().deviceType == vk::PhysicalDeviceType::eCpu;
  vk::ImageViewCreateInfo vci;
  vci.image = this->Image_;
  vci.viewType = vk::ImageViewType::e3D;
  vci.format = format;
  vci.subresourceRange = vk::ImageSubresourceRange{ vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1 };
  this->View_ = device.createImageView(vci);

  RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) {
    vk::ImageMemoryBarrier b;
    b.srcAccessMask = {};
    b.dstAccessMask = vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite |
      vk::AccessFlagBits::eTransferWrite | vk::AccessFlagBits::eTransferRead;
    b.oldLayout = vk::ImageLayout::eUndefined;
    b.newLayout = vk::ImageLayout::eGeneral;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = this->Image_;
    b.subresourceRange = vci.subresourceRange;
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTopOfPipe,
      vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer, {}, {}, {}, b);
  });
}

Image3D::~Image3D()
{
  vk::Device device = this->Context_->Device();
  device.destroyImageView(this->View_);
  device.destroyImage(this->Image_);
  device.freeMemory(this->Memory_);
}

uint64_t Image3D::Bytes() const
{
  return uint64_t(this->Extent_[0]) * this->Extent_[1] * this->Extent_[2] * TexelBytes(this->Format_);
}

Image3D::HostMemory Image3D::MapHostMemory()
{
  HostMemory m;
  if (this->HostMemoryType_)
  {
    try
    {
      m.Data = static_cast<char*>(this->Context_->Device().mapMemory(this->Memory_, 0, VK_WHOLE_SIZE));
      m.Bytes = this->MemoryBytes_;
    }
    catch (const vk::SystemError&)
    {
      m = HostMemory(); // only a speed-up: the upload goes on without it
    }
  }
  return m;
}

void Image3D::UnmapHostMemory()
{
  this->Context_->Device().unmapMemory(this->Memory_);
}

void Image3D::PrefaultPages(char* data, uint64_t bytes)
{
  constexpr uint64_t page = 4096;
  for (uint64_t i = 0; i < bytes; i += page)
  {
    reinterpret_cast<volatile char*>(data)[i] = 0;
  }
}

void Image3D::UploadSlices(const void* data, uint32_t z0, uint32_t count)
{
  if (count == 0)
  {
    return;
  }
  if (z0 + count > this->Extent_[2])
  {
    throw InputError("upload past the last slice of image '" + this->Name_ + "'");
  }
  uint64_t sliceBytes = uint64_t(this->Extent_[0]) * this->Extent_[1] * TexelBytes(this->Format_);
  // Stage in chunks no larger than the storage-buffer limit.
  uint64_t maxChunk = std::min<uint64_t>(this->Context_->Info().MaxStorageBufferRange, 64ull << 20);
  uint32_t slicesPerChunk = static_cast<uint32_t>(std::max<uint64_t>(1, maxChunk / sliceBytes));
  if (sliceBytes > maxChunk)
  {
    throw DeviceLimitError("one slice of image '" + this->Name_ + "' is larger than the staging limit");
  }
  const char* bytes = static_cast<const char*>(data);
  for (uint32_t z = 0; z < count; z += slicesPerChunk)
  {
    uint32_t n = std::min(slicesPerChunk, count - z);
    Buffer staging(this->Context_, sliceBytes * n, this->Name_ + " (staging)");
    staging.Upload(bytes + sliceBytes * z, sliceBytes * n);
    RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) {
      vk::BufferImageCopy region;
      region.bufferOffset = 0;
      region.imageSubresource = vk::ImageSubresourceLayers{ vk::ImageAspectFlagBits::eColor, 0, 0, 1 };
      region.imageOffset = vk::Offset3D{ 0, 0, static_cast<int32_t>(z0 + z) };
      region.imageExtent = vk::Extent3D{ this->Extent_[0], this->Extent_[1], n };
      Transition(cmd, this->Image_, vk::ImageLayout::eGeneral, vk::ImageLayout::eTransferDstOptimal);
      cmd.copyBufferToImage(staging.Handle(), this->Image_, vk::ImageLayout::eTransferDstOptimal, region);
      Transition(cmd, this->Image_, vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eGeneral);
    });
  }
}

void Image3D::Clear(float value)
{
  RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) {
    Transition(cmd, this->Image_, vk::ImageLayout::eGeneral, vk::ImageLayout::eTransferDstOptimal);
    VkClearColorValue color{};
    for (float& c : color.float32)
    {
      c = value;
    }
    const vk::ImageSubresourceRange range{ vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1 };
    cmd.clearColorImage(this->Image_, vk::ImageLayout::eTransferDstOptimal,
      reinterpret_cast<const vk::ClearColorValue&>(color), range);
    Transition(cmd, this->Image_, vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eGeneral);
  });
}

void Image3D::Upload(const void* data, uint64_t bytes)
{
  if (bytes != this->Bytes())
  {
    throw InputError("upload of " + std::to_string(bytes) + " bytes into image '" + this->Name_ +
      "' of " + std::to_string(this->Bytes()) + " bytes");
  }
  this->UploadSlices(data, 0, this->Extent_[2]);
}

void Image3D::Download(void* data, uint64_t bytes) const
{
  if (bytes != this->Bytes())
  {
    throw InputError("download of " + std::to_string(bytes) + " bytes from image '" + this->Name_ +
      "' of " + std::to_string(this->Bytes()) + " bytes");
  }
  uint64_t sliceBytes = uint64_t(this->Extent_[0]) * this->Extent_[1] * TexelBytes(this->Format_);
  uint64_t maxChunk = std::min<uint64_t>(this->Context_->Info().MaxStorageBufferRange, 64ull << 20);
  uint32_t slicesPerChunk = static_cast<uint32_t>(std::max<uint64_t>(1, maxChunk / sliceBytes));
  char* out = static_cast<char*>(data);
  for (uint32_t z = 0; z < this->Extent_[2]; z += slicesPerChunk)
  {
    uint32_t n = std::min(slicesPerChunk, this->Extent_[2] - z);
    Buffer staging(this->Context_, sliceBytes * n, this->Name_ + " (staging)");
    RunOnce(*this->Context_, [&](vk::CommandBuffer cmd) {
      Transition(cmd, this->Image_, vk::ImageLayout::eGeneral, vk::ImageLayout::eTransferSrcOptimal);
      vk::BufferImageCopy region;
      region.bufferOffset = 0;
      region.imageSubresource = vk::ImageSubresourceLayers{ vk::ImageAspectFlagBits::eColor, 0, 0, 1 };
      region.imageOffset = vk::Offset3D{ 0, 0, static_cast<int32_t>(z) };
      region.imageExtent = vk::Extent3D{ this->Extent_[0], this->Extent_[1], n };
      cmd.copyImageToBuffer(this->Image_, vk::ImageLayout::eTransferSrcOptimal, staging.Handle(), region);
      Transition(cmd, this->Image_, vk::ImageLayout::eTransferSrcOptimal, vk::ImageLayout::eGeneral);
    });
    staging.Download(out + sliceBytes * z, sliceBytes * n);
  }
}
}
