#include "vsRenderTargetLimits.h"

#include "vsContext.h"
#include "vsError.h"

#include <unistd.h>

#include <sstream>

namespace vs
{
namespace
{
std::string MiB(uint64_t bytes)
{
  std::ostringstream os;
  os << (bytes >> 20) << " MiB";
  return os.str();
}
}

uint64_t RenderTargetLimits::HostMemoryBytes()
{
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : 0;
}

std::string RenderTargetLimits::Problem(const Context& context, uint32_t width, uint32_t height)
{
  const DeviceInfo& info = context.Info();
  const uint64_t pixels = uint64_t(width) * height;
  std::ostringstream os;
  os << "a " << width << " x " << height << " render (" << pixels << " pixels) ";
  const std::string what = os.str();
  if (pixels == 0)
  {
    return what + "has no pixels";
  }
  const uint64_t largest = pixels * LargestBufferBytesPerPixel;
  if (info.MaxStorageBufferRange && largest > info.MaxStorageBufferRange)
  {
    return what + "needs accumulation buffers of " + MiB(largest) + " each, more than the device's "
      "maxStorageBufferRange of " + MiB(info.MaxStorageBufferRange) + " (" +
      std::to_string(info.MaxStorageBufferRange) + " bytes) on '" + info.Name + "'";
  }
  const uint64_t device = pixels * DeviceBytesPerPixel;
  if (info.DeviceLocalHeapBytes && device > info.DeviceLocalHeapBytes)
  {
    return what + "needs " + MiB(device) + " of device memory, more than the " + MiB(info.DeviceLocalHeapBytes) +
      " device-local heap of '" + info.Name + "'";
  }
  const uint64_t groups[2] = { (uint64_t(width) + WorkGroupSide - 1) / WorkGroupSide,
    (uint64_t(height) + WorkGroupSide - 1) / WorkGroupSide };
  for (int i = 0; i < 2; ++i)
  {
    if (info.MaxComputeWorkGroupCount[i] && groups[i] > info.MaxComputeWorkGroupCount[i])
    {
      return what + "needs " + std::to_string(groups[i]) + " work groups along " + (i ? "y" : "x") +
        ", more than the device's maxComputeWorkGroupCount[" + std::to_string(i) + "] of " +
        std::to_string(info.MaxComputeWorkGroupCount[i]);
    }
  }
  const uint64_t host = pixels * HostBytesPerPixel;
  const uint64_t memory = HostMemoryBytes();
  if (memory && host > memory / 2)
  {
    return what + "needs about " + MiB(host) + " of host memory (" + std::to_string(HostBytesPerPixel) +
      " bytes a pixel), more than half of this host's " + MiB(memory);
  }
  return std::string();
}

void RenderTargetLimits::Check(const Context& context, uint32_t width, uint32_t height)
{
  const std::string problem = Problem(context, width, height);
  if (!problem.empty())
  {
    throw DeviceLimitError(problem);
  }
}
}
