#include "vsDeviceEnvironment.h"
#include "vsBuffer.h"
#include "vsEnvironmentMap.h"
#include "vsError.h"
#include "vsSerial.h"
#include "sampling/vs_prelude.h"

#include <algorithm>
#include <string>
#include <vector>

namespace vs
{
namespace
{
const int kHostLevels = 6; // up to 64 x 64, the largest visibility direction resolution
}

DeviceEnvironment::DeviceEnvironment(std::shared_ptr<Context> context, const EnvironmentMap& source, int minSize)
  : Serial_(NewSerial())
{
  if (source.Empty() || !EnvironmentMap::IsPowerOfTwo(source.Size))
  {
    throw InputError("the environment map is empty or not a power of two in size");
  }
  // Refine small maps so that the product with a D x D visibility map has a level log2(D).
  EnvironmentMap refined;
  const EnvironmentMap* map = &source;
  if (source.Size < minSize)
  {
    refined = EnvironmentMap::Allocate(minSize);
    const int f = minSize / source.Size;
    for (int y = 0; y < minSize; ++y)
    {
      for (int x = 0; x < minSize; ++x)
      {
        glm::vec3 v = source.Texel(x / f, y / f);
        float* t = &refined.Radiance[3 * (size_t(y) * minSize + x)];
        t[0] = v.x;
        t[1] = v.y;
        t[2] = v.z;
      }
    }
    refined.Finalize();
    map = &refined;
  }
  this->Size_ = map->Size;
  this->Level_ = map->Levels() - 1;
  const size_t texels = size_t(map->Size) * map->Size;
  std::vector<float> rgba(4 * texels, 0.0f);
  // The luminance in double, with vs_luminance's weights (sampling/vs_prelude.h).
  const double weights[3] = { VS_LUMINANCE_WEIGHTS };
  for (size_t i = 0; i < texels; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgba[4 * i + c] = map->Radiance[3 * i + c];
    }
    this->MaxLuminance_ = std::max(this->MaxLuminance_,
      weights[0] * map->Radiance[3 * i] + weights[1] * map->Radiance[3 * i + 1] + weights[2] * map->Radiance[3 * i + 2]);
  }
  this->Radiance_ = std::make_unique<Buffer>(context, rgba.size() * sizeof(float), "environment radiance");
  this->Radiance_->Upload(rgba.data(), rgba.size() * sizeof(float));
  this->Mips_ = std::make_unique<Buffer>(context, map->ImportanceMips.size() * sizeof(float), "environment importance");
  this->Mips_->Upload(map->ImportanceMips.data(), map->ImportanceMips.size() * sizeof(float));
  const int coarsest = std::min(this->Level_, kHostLevels);
  this->CoarseMips_.assign(map->ImportanceMips.begin(),
    map->ImportanceMips.begin() + std::ptrdiff_t(EnvironmentMap::MipOffset(coarsest + 1)));
  // The radiance at the finest kept level: its coarser levels are exact means of it (nested texels).
  const std::vector<glm::vec3> coarse = map->MeanRadianceLevel(1 << coarsest);
  this->Coarse_ = std::make_unique<EnvironmentMap>(EnvironmentMap::Allocate(1 << coarsest));
  for (size_t i = 0; i < coarse.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Coarse_->Radiance[3 * i + c] = coarse[i][c];
    }
  }
}

void DeviceEnvironment::CheckHostLevel(int level) const
{
  if (level < 0 || level > std::min(this->Level_, kHostLevels))
  {
    throw InputError("environment level " + std::to_string(level) + " is not kept (levels 0.." +
      std::to_string(std::min(this->Level_, kHostLevels)) + ")");
  }
}

std::vector<glm::vec3> DeviceEnvironment::RadianceLevel(int level) const
{
  this->CheckHostLevel(level);
  return this->Coarse_->MeanRadianceLevel(1 << level);
}

std::vector<float> DeviceEnvironment::ImportanceLevel(int level) const
{
  this->CheckHostLevel(level);
  const size_t first = EnvironmentMap::MipOffset(level), last = EnvironmentMap::MipOffset(level + 1);
  return std::vector<float>(this->CoarseMips_.begin() + std::ptrdiff_t(first), this->CoarseMips_.begin() + std::ptrdiff_t(last));
}

DeviceEnvironment::~DeviceEnvironment() = default;
}
