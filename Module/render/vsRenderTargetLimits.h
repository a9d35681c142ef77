// vsRenderTargetLimits.h — whether a width x height render fits the device and the host, checked
// before anything is allocated (issue 13, item 7). A 16384 x 16384 render used to grow past 10 GB
// of host memory (the window's depth read back, its subsampled copy, the pass's copy) before
// the first accumulator (4 GiB) hit the device's maxStorageBufferRange; under a memory limit it
// crashed in a lavapipe worker instead. Every check names the limit and the numbers.
#ifndef vsRenderTargetLimits_h
#define vsRenderTargetLimits_h

#include "vissweepCoreModule.h"

#include <cstdint>
#include <string>

namespace vs
{
class Context;

class VISSWEEPCORE_EXPORT RenderTargetLimits
{
public:
  /** Device bytes a pixel of a progressive render holds: three accumulators of 4 floats (sum,
   *  compensation, squares), its depth, and under full transport its path in flight (4 x 16 bytes,
   *  path_state.glsl). The largest buffer is 16 bytes a pixel. */
  static constexpr uint64_t DeviceBytesPerPixel = 3 * 16 + 4 + 4 * 16;
  static constexpr uint64_t LargestBufferBytesPerPixel = 16;
  /** Host bytes a pixel costs at the peak of a frame and its outputs, rounded up: the window's
   *  depth and the per-pass copies (12), the mean and the display image (32), the radiance image
   *  (16), the variance with its read-backs (64), the written image (16), the window's own
   *  colour and depth (8). */
  static constexpr uint64_t HostBytesPerPixel = 160;
  /** Pixels a work group of the render kernels covers along x and along y. */
  static constexpr uint32_t WorkGroupSide = 8;

  /** The reason a width x height render cannot run on `context`'s device or this host, naming the
   *  limit; "" when it fits. Checks: the largest buffer against maxStorageBufferRange, all
   *  buffers against the device-local heap, the work groups against maxComputeWorkGroupCount,
   *  and the host's share against half of the host's physical memory. */
  static std::string Problem(const Context& context, uint32_t width, uint32_t height);
  /** Throws DeviceLimitError with Problem() when it is not empty. */
  static void Check(const Context& context, uint32_t width, uint32_t height);

  /** The host's physical memory in bytes (0 if unknown: then the host check is skipped). */
  static uint64_t HostMemoryBytes();
};
}

#endif
