#include "vsSceneLightParams.h"
#include "vsError.h"

#include <cmath>
#include <string>

namespace vs
{
namespace
{
bool Finite(const glm::vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}

void SceneLightParams::Check(const shared::VsMonteCarloParams& params)
{
  if (params.lightCount > shared::VS_MAX_SCENE_LIGHTS)
  {
    throw InputError("the Monte Carlo estimate takes at most " + std::to_string(shared::VS_MAX_SCENE_LIGHTS) +
      " lights, got " + std::to_string(params.lightCount));
  }
  for (uint32_t i = 0; i < params.lightCount; ++i)
  {
    const shared::VsSceneLight& l = params.lights[i];
    const std::string name = "light " + std::to_string(i);
    if (l.kind != shared::VS_LIGHT_DIRECTIONAL && l.kind != shared::VS_LIGHT_POSITIONAL)
    {
      throw InputError(name + ": unknown kind " + std::to_string(l.kind));
    }
    if (!Finite(l.irradiance) || l.irradiance.x < 0.0f || l.irradiance.y < 0.0f || l.irradiance.z < 0.0f)
    {
      throw InputError(name + ": its intensity times colour must be finite and >= 0");
    }
    if (!Finite(l.direction) || std::abs(glm::length(l.direction) - 1.0f) > 1e-3f)
    {
      throw InputError(name + ": its direction must be a unit vector (position and focal point apart)");
    }
    if (!Finite(l.position) || !Finite(l.attenuation) || l.attenuation.x < 0.0f || l.attenuation.y < 0.0f ||
      l.attenuation.z < 0.0f || !std::isfinite(l.cosCone) || !(l.exponent >= 0.0f && std::isfinite(l.exponent)))
    {
      throw InputError(name + ": its position, attenuation (>= 0), cone and exponent (>= 0) must be finite");
    }
  }
}

bool SceneLightParams::Make(shared::VsSceneLight& light, bool positional, const glm::dvec3& position,
  const glm::dvec3& focalPoint, double intensity, const glm::dvec3& color, double coneAngle, double exponent,
  const glm::dvec3& attenuation)
{
  const glm::dvec3 axis = focalPoint - position;
  const double length = glm::length(axis);
  const bool spot = positional && coneAngle < 90.0;
  if ((!positional || spot) && !(length > 0.0 && std::isfinite(length)))
  {
    return false;
  }
  light = shared::VsSceneLight{};
  light.kind = positional ? shared::VS_LIGHT_POSITIONAL : shared::VS_LIGHT_DIRECTIONAL;
  light.position = glm::vec3(position);
  light.direction = length > 0.0 && std::isfinite(length) ? glm::vec3(axis / length) : glm::vec3(0.0f, 0.0f, -1.0f);
  light.cosCone = spot ? float(std::cos(std::max(0.0, coneAngle) * M_PI / 180.0)) : -2.0f;
  light.irradiance = glm::vec3(M_PI * intensity * color);
  light.exponent = float(std::max(0.0, exponent));
  light.attenuation = glm::vec3(attenuation);
  return true;
}
}
