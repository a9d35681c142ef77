// vsStagedUpload.h — uploads slices of one or more 3D images (of equal width and height) through a
// small ring of staging buffers made once and reused for the whole upload: the host fills one chunk
// of slices in place while the queue copies the chunks before it. One per thread (it has its own
// command pool; submissions take the context's queue lock only to submit).
//
// Issue 39: ch2better's upload made a staging buffer, a command buffer and a fence per slice and
// waited for each copy under the queue lock (632 round trips for its float image and quads), after
// the scalars had been copied into a 141 MB float vector and into each staging buffer again. The
// caller now writes each slice's texels straight into the staging memory, which stays in the cache.
#ifndef vsStagedUpload_h
#define vsStagedUpload_h

#include "vsVulkan.h"
#include "vissweepCoreModule.h"

#include <memory>
#include <vector>

namespace vs
{
class Buffer;
class Context;
class Image3D;

class VISSWEEPCORE_EXPORT StagedUpload
{
public:
  /** `images` must outlive the upload and share width and height; chunks of at most
   *  `slicesPerChunk` slices (at least 1) of every image, `ring` (at least 1) staging buffers. */
  StagedUpload(std::shared_ptr<Context> context, std::vector<Image3D*> images, uint32_t slicesPerChunk,
    uint32_t ring = 3);
  /** Waits for the copies in flight (without throwing). */
  ~StagedUpload();
  StagedUpload(const StagedUpload&) = delete;
  StagedUpload& operator=(const StagedUpload&) = delete;

  /** Slices per chunk: about `bytes` of staging for all images together, at least 1. */
  static uint32_t SlicesPerChunk(const std::vector<Image3D*>& images, uint64_t bytes);

  /** Starts a chunk of slices [z0, z0 + count) (count <= the chunk size) of every image, waiting
   *  first for the copy that used its staging buffer last. */
  void Begin(uint32_t z0, uint32_t count);
  /** Where image i's texels of the chunk go: tightly packed, x fastest, in its format. */
  void* Texels(size_t image);
  /** Copies the chunk to the images (asynchronously; barriers make the texels visible to shaders
   *  and transfers submitted after it, the images back in GENERAL). */
  void Submit();
  /** Waits for every copy submitted; throws on a device error. */
  void Finish();

private:
  struct Slot;
  void Wait(Slot& slot);

  std::shared_ptr<Context> Context_;
  std::vector<Image3D*> Images_;
  uint32_t SlicesPerChunk_;
  uint64_t SliceTexels_;
  vk::CommandPool Pool_;
  std::vector<std::unique_ptr<Slot>> Slots_;
  size_t Next_ = 0;
  Slot* Current_ = nullptr;
  uint32_t Z0_ = 0, Count_ = 0;
};
}

#endif
