// vsSceneLightParams.h — the core's side of VTK's lights in the Monte Carlo estimate (issue 38; the
// kernel's side is scene_lights.glsl, the light model sampling/scene_lights.h): whether a render compiles
// them, the check of the parameters' lights, and lights made from VTK's terms (the Rendering module's
// vsSceneLights.h reads them off a vtkRenderer).
#ifndef vsSceneLightParams_h
#define vsSceneLightParams_h

#include "sampling/mc_params.h"
#include "vissweepCoreModule.h"

#include <glm/glm.hpp>

namespace vs
{
class VISSWEEPCORE_EXPORT SceneLightParams
{
public:
  /** Whether the render kernel compiles VTK's lights (its specialization constant 17, VS_SPEC_LIGHTS). */
  static bool Enabled(const shared::VsMonteCarloParams& params) { return params.lightCount > 0u; }

  /** Throws InputError naming the light and the value: more than VS_MAX_SCENE_LIGHTS, an unknown kind,
   *  a non-finite or negative irradiance, attenuation or exponent, a direction that is not unit length, a
   *  non-finite position or cone. */
  static void Check(const shared::VsMonteCarloParams& params);

  /** A light in VTK's terms (vtkLight): a directional light travelling from `position` towards
   *  `focalPoint`, or positional at `position`; intensity and colour (irradiance pi x intensity x colour
   *  on a plane facing it, sampling/scene_lights.h); a positional light's cone angle (degrees, >= 90: no
   *  cone), exponent and attenuation. False (and nothing made) when position and focal point coincide for
   *  a directional light or a spot. */
  static bool Make(shared::VsSceneLight& light, bool positional, const glm::dvec3& position,
    const glm::dvec3& focalPoint, double intensity, const glm::dvec3& color, double coneAngle, double exponent,
    const glm::dvec3& attenuation);
};
}

#endif
