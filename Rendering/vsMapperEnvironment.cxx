#include "vsMapperEnvironment.h"

#include "vsError.h"
#include "vsLightDirections.h"

#include "vtkEnvironmentMapAlgorithm.h"
#include "vtkImageData.h"

#include <algorithm>
#include <string>

namespace vs
{
bool MapperEnvironment::Update(const std::shared_ptr<Context>& context, vtkImageData* image, int side)
{
  if (!this->DeviceMap || (image && image->GetMTime() != this->Time) || (!image && !this->Default))
  {
    std::shared_ptr<const vs::EnvironmentMap> map;
    if (image)
    {
      std::string error;
      map = vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(image, &error);
      if (!map)
      {
        throw vs::InputError("the environment input is not an environment map: " + error);
      }
    }
    else
    {
      map = std::make_shared<vs::EnvironmentMap>(vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
    }
    this->DeviceMap.reset();
    this->Source = map;
    this->DeviceMap = std::make_unique<vs::DeviceEnvironment>(context, *map, std::max(8, side));
    this->Time = image ? image->GetMTime() : 0;
    this->Default = image == nullptr;
    return true;
  }
  else if (this->DeviceMap->Size() < side)
  {
    // The direction resolution grew past the map's: the product needs importance level log2(D).
    this->DeviceMap.reset();
    this->DeviceMap = std::make_unique<vs::DeviceEnvironment>(context, *this->Source, side);
    return true;
  }
  return false;
}

const std::vector<glm::vec3>& MapperEnvironment::LightDirections(int uploads, int side)
{
  const std::pair<int, int> key(uploads, side);
  if (this->DirectionsKey != key)
  {
    this->Directions = vs::LightWeightedDirections(*this->Source, uint32_t(side));
    this->DirectionsKey = key;
  }
  return this->Directions;
}

void MapperEnvironment::Release()
{
  this->DeviceMap.reset();
  this->Source.reset();
  this->Time = 0;
  this->Default = false;
  this->Directions.clear();
  this->DirectionsKey = { -1, -1 };
}
}
