// vsImage.h — a 3D storage image on the device (volumes, visibility grids).
//
// Kept in VK_IMAGE_LAYOUT_GENERAL for its whole life, read and written by the
// shaders with imageLoad/imageStore. Creation checks the extent against
// maxImageDimension3D and the format's limits before anything is allocated.
#ifndef vsImage_h
#define vsImage_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <memory>
#include <string>

namespace vs
{
class Context;

class VISSWEEPCORE_EXPORT Image3D
{
public:
  /** Supported formats: eR32Sfloat, eR32Uint, eR16Unorm, eR8Unorm, eR16Sfloat, eR32G32B32A32Sfloat. */
  Image3D(std::shared_ptr<Context> context, uint32_t width, uint32_t height, uint32_t depth,
    vk::Format format, const std::string& name);
  ~Image3D();
  Image3D(const Image3D&) = delete;
  Image3D& operator=(const Image3D&) = delete;

  /** Bytes per texel of a supported format. */
  static uint32_t TexelBytes(vk::Format format);

  /** Throws DeviceLimitError if an image of this size and format cannot exist on the device. */
  static void CheckLimits(Context& context, uint32_t width, uint32_t height, uint32_t depth,
    vk::Format format, const std::string& name);

  /** Whole-image transfers, tightly packed x fastest, in the image's texel format. */
  void Upload(const void* data, uint64_t bytes);
  void Download(void* data, uint64_t bytes) const;
  /** Sets every texel to `value` (every channel; unorm formats clamp it to [0, 1]). */
  void Clear(float value);
  /** Uploads only slices [z0, z0 + count). */
  void UploadSlices(const void* data, uint32_t z0, uint32_t count);

  vk::Image Handle() const { return this->Image_; }
  vk::ImageView View() const { return this->View_; }
  vk::Format Format() const { return this->Format_; }
  uint32_t Width() const { return this->Extent_[0]; }
  uint32_t Height() const { return this->Extent_[1]; }
  uint32_t Depth() const { return this->Extent_[2]; }
  uint64_t Bytes() const;

  /** The image's memory as the host sees it, on a CPU device (lavapipe: device memory is the host's
   *  own, host-visible), to fault its pages in ahead of an upload (PrefaultPages); empty on any
   *  other device, whose memory faults nothing on the host. Map once, then UnmapHostMemory(). */
  struct HostMemory
  {
    char* Data = nullptr;
    uint64_t Bytes = 0;
  };
  HostMemory MapHostMemory();
  void UnmapHostMemory();
  /** Writes a zero into every 4 KB page of [data, data + bytes) on the calling thread, so that the
   *  kernel backs them now (issue 39: on this VM the first touch of fresh memory costs ~2.3 ms per
   *  MB, and an upload's copy touches it on the driver's one queue thread; slabs of host threads
   *  fault it in parallel). It writes: only for memory none of which is written yet (finish every
   *  range before any copy into the image starts) and all of which is written afterwards. */
  static void PrefaultPages(char* data, uint64_t bytes);
  const std::string& Name() const { return this->Name_; }

private:
  std::shared_ptr<Context> Context_;
  std::string Name_;
  uint32_t Extent_[3];
  vk::Format Format_;
  vk::Image Image_;
  vk::ImageView View_;
  vk::DeviceMemory Memory_;
  uint64_t MemoryBytes_ = 0;
  bool HostMemoryType_ = false; // host-visible memory on a CPU device
};
}

#endif
