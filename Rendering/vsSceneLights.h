// vsSceneLights.h — the renderer's vtkLights as lights of the Monte Carlo estimate (issue 38): every
// switched-on light but VTK's automatic headlight, in world space (a headlight at the camera looking at
// its focal point, a camera light through the camera's light transform, a scene light through its own
// transform), with VTK's intensity, diffuse colour, positional flag, cone angle, exponent and
// attenuation (sampling/scene_lights.h: the model; docs/reference.md "VTK's lights": the rules).
// Internal to VisSweep (hidden from the wrappers).
#ifndef vsSceneLights_h
#define vsSceneLights_h

#include "sampling/mc_params.h"

#include <string>
#include <vector>

class vtkLight;
class vtkRenderer;

namespace vs
{
class SceneLights
{
public:
  /** Fills params.lightCount and params.lights from the renderer's lights; returns how many switched-on
   *  lights were left out (beyond VS_MAX_SCENE_LIGHTS). With `withAutomaticHeadlight` VTK's automatic
   *  headlight is a light too (the emission-absorption mode's Phong shading, as VTK's GPU mapper lights
   *  with it). `followsCamera`, if given: bit i set where light i follows the camera (a headlight or a
   *  camera light: it moves with every camera move). `leftOut`, if given: the left-out lights' positions
   *  in the renderer's light collection (from 0). */
  static int Set(shared::VsMonteCarloParams& params, vtkRenderer* renderer, bool withAutomaticHeadlight = false,
    uint32_t* followsCamera = nullptr, std::vector<int>* leftOut = nullptr);

  /** "" when every light Set takes is used; else a warning naming how many switched-on lights the
   *  renderer has, how many are used and which are left out (their positions in vtkRenderer::GetLights(),
   *  counted from 1). */
  static std::string LeftOutWarning(vtkRenderer* renderer);

  /** Whether `light` is what VTK's renderer creates by itself when no light is on (vtkRenderer::
   *  CreateLight): a headlight at vtkLight's defaults (intensity 1, white, not positional). The estimate
   *  leaves it out, with an environment and without one: the environment (or the default white sky) is
   *  then the scene's light, and images rendered before VTK's lights were honoured stay as they were. */
  static bool IsAutomaticHeadlight(vtkLight* light);
};
}

#endif
