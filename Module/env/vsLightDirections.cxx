#include "vsLightDirections.h"

#include "vsEnvironmentMap.h"
#include "vsError.h"
#include "sampling/octahedral.h"

#include <cmath>
#include <string>

namespace vs
{
std::vector<glm::vec3> LightWeightedDirections(const EnvironmentMap& map, uint32_t side)
{
  const uint32_t n = uint32_t(map.Size);
  if (side == 0 || (side & (side - 1)) != 0 || n < side || n % side != 0)
  {
    throw InputError("light-weighted directions need a power-of-two resolution of at most the map's " +
      std::to_string(n) + ", got " + std::to_string(side));
  }
  std::vector<glm::dvec3> sum(size_t(side) * side, glm::dvec3(0.0));
  const uint32_t f = n / side;
  const float* leaves = map.Mip(int(std::log2(double(n)) + 0.5));
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x)
    {
      const double w = double(leaves[size_t(y) * n + x]);
      if (w > 0.0 && std::isfinite(w))
      {
        sum[size_t(y / f) * side + x / f] += w * glm::dvec3(shared::vs_texel_dir(glm::uvec2(x, y), n));
      }
    }
  std::vector<glm::vec3> out(sum.size());
  for (uint32_t t = 0; t < out.size(); ++t)
  {
    const double l = glm::length(sum[t]);
    out[t] = l > 0.0 && std::isfinite(l) ? glm::vec3(sum[t] / l)
                                         : shared::vs_texel_dir(glm::uvec2(t % side, t / side), side);
  }
  return out;
}
}
