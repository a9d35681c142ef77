// vsBuffer.h — a storage buffer on the device, with upload and download; also readable as a
// uniform texel buffer (TexelView) where a shader reads it at divergent indices.
//
// Memory: device-local and host-visible where the device has such memory
// (lavapipe, integrated GPUs, resizable BAR), so transfers are plain copies;
// otherwise device-local memory filled through a staging buffer.
#ifndef vsBuffer_h
#define vsBuffer_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace vs
{
class Context;

class VISSWEEPCORE_EXPORT Buffer
{
public:
  /** Throws DeviceLimitError when bytes exceed maxStorageBufferRange or the heap. */
  Buffer(std::shared_ptr<Context> context, uint64_t bytes, const std::string& name);
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  void Upload(const void* data, uint64_t bytes, uint64_t offset = 0);
  void Download(void* data, uint64_t bytes, uint64_t offset = 0) const;
  void Fill(uint32_t value);

  /** The whole buffer as texels of `format` (eR32Sfloat, eR32Uint or eR32G32B32A32Sfloat), for a
   *  uniform texel buffer binding (made once per format). lavapipe loads a texel buffer at
   *  per-lane indices with one vector gather, a storage buffer with a scalar loop over the lanes.
   *  Throws DeviceLimitError past the device's maxTexelBufferElements. */
  vk::BufferView TexelView(vk::Format format) const;

  vk::Buffer Handle() const { return this->Buffer_; }
  uint64_t Size() const { return this->Bytes_; }
  /** The buffer's memory on the host when it is host-visible (mapped for its life), else nullptr. */
  void* Mapped() const { return this->Mapped_; }
  const std::string& Name() const { return this->Name_; }

private:
  std::shared_ptr<Context> Context_;
  std::string Name_;
  uint64_t Bytes_ = 0;
  vk::Buffer Buffer_;
  vk::DeviceMemory Memory_;
  void* Mapped_ = nullptr; // when host-visible
  mutable std::vector<std::pair<vk::Format, vk::BufferView>> Views_;
};

/** Allocates device memory for the requirements, preferring host-visible device-local memory.
 *  Sets hostVisible. Throws DeviceLimitError naming `what` when it cannot. */
VISSWEEPCORE_EXPORT vk::DeviceMemory AllocateMemory(Context& context,
  const vk::MemoryRequirements& req, bool allowHostVisible, bool& hostVisible, const std::string& what);

/** Runs `record` in a one-time command buffer and waits for it. */
VISSWEEPCORE_EXPORT void RunOnce(Context& context, const std::function<void(vk::CommandBuffer)>& record);
}

#endif
