#include "vsSerial.h"

#include <atomic>

namespace vs
{
uint64_t NewSerial()
{
  static std::atomic<uint64_t> next{ 1 };
  return next.fetch_add(1, std::memory_order_relaxed);
}
}
