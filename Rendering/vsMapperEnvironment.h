// vsMapperEnvironment.h — the mapper's environment on the device: the map of its input port 1 (or,
// without one, a constant white sky of radiance 1), uploaded again when the input changes or the
// direction resolution grows past the map's importance levels; and the grid's light-weighted
// directions made from it, kept until the map or the resolution changes. Not wrapped.
#ifndef vsMapperEnvironment_h
#define vsMapperEnvironment_h

#include "vsDeviceEnvironment.h"
#include "vsEnvironmentMap.h"

#include "vtkType.h"

#include <glm/glm.hpp>

#include <memory>
#include <utility>
#include <vector>

class vtkImageData;

namespace vs
{
class Context;

class MapperEnvironment
{
public:
  /** Uploads the map of `image` (an environment map image; nullptr: the white sky) if it is new or
   *  changed, or again at `side` directions when the upload has fewer. Returns whether it uploaded;
   *  throws vs::InputError for an image that is not an environment map. */
  bool Update(const std::shared_ptr<Context>& context, vtkImageData* image, int side);
  /** The uploaded map (after a successful Update()). */
  DeviceEnvironment& Device() { return *this->DeviceMap; }
  /** The host map it was uploaded from. */
  const EnvironmentMap& Map() const { return *this->Source; }
  /** Whether there is a map of at least `side` texels a side to make light directions from. */
  bool HasLightDirections(int side) const { return this->Source && this->Source->Size >= side; }
  /** Per grid texel of a `side` x `side` direction map, where its light comes from; made again
   *  when `uploads` (the upload count) or `side` changed. */
  const std::vector<glm::vec3>& LightDirections(int uploads, int side);
  /** Frees the device map and forgets the host one: the next Update() uploads. */
  void Release();

private:
  std::unique_ptr<DeviceEnvironment> DeviceMap;
  std::shared_ptr<const EnvironmentMap> Source;
  vtkMTimeType Time = 0;
  bool Default = false;
  std::vector<glm::vec3> Directions; // per grid texel, where its light comes from
  std::pair<int, int> DirectionsKey{ -1, -1 }; // (environment upload, D) they were made for
};
}

#endif
