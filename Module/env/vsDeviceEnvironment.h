// vsDeviceEnvironment.h — an environment map on the device: the equal-area
// octahedral radiance (one vec4 per texel) and its luminance importance quadtree
// (the flat mip array of vs::EnvironmentMap), as the render pass reads them.
#ifndef vsDeviceEnvironment_h
#define vsDeviceEnvironment_h

#include "vissweepCoreModule.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace vs
{
class Buffer;
class Context;
class EnvironmentMap;

class VISSWEEPCORE_EXPORT DeviceEnvironment
{
public:
  /** Uploads `map`; maps smaller than minSize texels per side are refined (each texel
   *  split into its 4 children, which is exact for piecewise-constant texels). */
  DeviceEnvironment(std::shared_ptr<Context> context, const EnvironmentMap& map, int minSize = 8);
  ~DeviceEnvironment();

  const Buffer& Radiance() const { return *this->Radiance_; }
  const Buffer& Mips() const { return *this->Mips_; }
  int Size() const { return this->Size_; }
  /** log2(Size): the finest level of the quadtree. */
  int FinestLevel() const { return this->Level_; }
  /** The largest radiance of any texel (luminance), for sanity bounds. */
  double MaxLuminance() const { return this->MaxLuminance_; }
  bool IsBlack() const { return this->MaxLuminance_ <= 0.0; }
  /** A process-wide serial of this upload (vsSerial.h): a DeviceEnvironment never changes, so a new
   *  map is a new serial even where a new object reuses an old one's address. */
  uint64_t Serial() const { return this->Serial_; }
  /** The luminance importance at quadtree level `level` (2^level x 2^level nodes, row-major,
   *  the same octahedral texels as a D x D visibility map with D = 2^level), kept on the host
   *  for levels up to 6. Throws InputError beyond FinestLevel() or 6. */
  std::vector<float> ImportanceLevel(int level) const;
  /** The mean RGB radiance over each node of the same level (EnvironmentMap::MeanRadianceLevel):
   *  times 4 pi / 4^level, the exact integral over the node of the radiance the renderer looks up
   *  (before the renderer's intensity). Luminance(RadianceLevel(l)[n]) is ImportanceLevel(l)[n] up
   *  to float rounding. Throws InputError beyond FinestLevel() or 6. */
  std::vector<glm::vec3> RadianceLevel(int level) const;

private:
  std::unique_ptr<Buffer> Radiance_, Mips_;
  int Size_ = 0, Level_ = 0;
  double MaxLuminance_ = 0.0;
  uint64_t Serial_ = 0;
  std::vector<float> CoarseMips_; // levels 0..min(Level_, 6) of the importance quadtree
  std::unique_ptr<EnvironmentMap> Coarse_; // the map's mean radiance at level min(Level_, 6)
  void CheckHostLevel(int level) const;
};
}

#endif
