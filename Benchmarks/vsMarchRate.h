// vsMarchRate.h — how fast the device reads the volume in the plainest ray march
// (march_rate.comp: parallel rays, trilinear sample + classification per step):
// the ceiling the Monte Carlo kernel's volume-sample rate is compared against.
#ifndef vsMarchRate_h
#define vsMarchRate_h

#include "vissweepCoreModule.h"

#include <array>
#include <cstdint>
#include <memory>

namespace vs
{
class Context;
class DeviceVolume;
class TransferFunctionTable;

struct MarchRate
{
  uint64_t Samples = 0;  // trilinear samples (8 imageLoads each) of one march
  double Seconds = 0.0;  // device seconds of the fastest of the repeats
  double SamplesPerSecond() const { return this->Seconds > 0.0 ? double(this->Samples) / this->Seconds : 0.0; }
};

/** Marches rays x rays parallel rays along a diagonal through the whole volume, at `step`
 *  voxels, `repeats` times (after one warm-up that includes shader compilation). */
VISSWEEPCORE_EXPORT MarchRate MeasureMarchRate(const std::shared_ptr<Context>& context, const DeviceVolume& volume,
  const TransferFunctionTable& tf, const std::array<uint32_t, 3>& dims, uint32_t rays = 512, float step = 0.5f,
  int repeats = 3);
}

#endif
