// vsParallelSlabs.h — host loops over a volume's slices, split into contiguous slabs, one per thread
// (the calling thread included): the scene's conversion, upload, 8-bit quads and brick ranges, which
// a first frame waits for (issue 39: a 35 M voxel volume's host work took most of its first frame on
// one core while the other sat idle). Each slab's work must not depend on another's; what the slabs
// combine (min, max, counts) the caller combines, so results do not depend on the split.
#ifndef vsParallelSlabs_h
#define vsParallelSlabs_h

#include "vissweepCoreModule.h"

#include <cstdint>
#include <functional>

namespace vs
{
/** Threads the host loops use: $VISSWEEP_HOST_THREADS (1 = serial), else the hardware's, at most 8. */
VISSWEEPCORE_EXPORT unsigned HostThreads();
/** The slabs ForSlabs splits `count` items into: min(HostThreads(), count), at least 1. */
VISSWEEPCORE_EXPORT unsigned SlabCount(uint64_t count);
/** Calls body(slab, begin, end) for each of SlabCount(count) slabs of [0, count), slab 0 on this
 *  thread, the others on threads of their own; returns when all are done, rethrowing the first
 *  slab's exception if any threw. */
VISSWEEPCORE_EXPORT void ForSlabs(
  uint64_t count, const std::function<void(unsigned slab, uint64_t begin, uint64_t end)>& body);
}

#endif
