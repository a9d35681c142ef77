// vsSerial.h — process-wide serial numbers for device contents. An object whose contents change
// takes a new serial, so a cache keyed on serials (the direction table on a visibility grid and an
// environment) can tell new contents from old even when a new object reuses an old one's address.
#ifndef vsSerial_h
#define vsSerial_h

#include "vissweepCoreModule.h"

#include <cstdint>

namespace vs
{
/** A number no earlier call returned (never 0), thread-safe. */
VISSWEEPCORE_EXPORT uint64_t NewSerial();
}

#endif
