#include "vsSceneLights.h"
#include "vsSceneLightParams.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"

#include <glm/glm.hpp>

namespace vs
{
bool SceneLights::IsAutomaticHeadlight(vtkLight* light)
{
  const double* c = light->GetDiffuseColor();
  return light->LightTypeIsHeadlight() && light->GetIntensity() == 1.0 && c[0] == 1.0 && c[1] == 1.0 &&
    c[2] == 1.0 && !light->GetPositional();
}

std::string SceneLights::LeftOutWarning(vtkRenderer* renderer)
{
  shared::VsMonteCarloParams scratch{};
  std::vector<int> leftOut;
  Set(scratch, renderer, false, nullptr, &leftOut);
  if (leftOut.empty())
  {
    return std::string();
  }
  const int used = int(scratch.lightCount);
  std::string positions;
  for (size_t i = 0; i < leftOut.size(); ++i)
  {
    positions += (i == 0 ? "" : i + 1 == leftOut.size() ? " and " : ", ") + std::to_string(leftOut[i] + 1);
  }
  return "the renderer has " + std::to_string(used + int(leftOut.size())) +
    " switched-on lights (VTK's automatic headlight not counted): the Monte Carlo estimate uses at most " +
    std::to_string(shared::VS_MAX_SCENE_LIGHTS) + ", the first " + std::to_string(used) +
    "; it leaves out the light" + (leftOut.size() > 1 ? "s" : "") + " at position" + (leftOut.size() > 1 ? "s " : " ") +
    positions + " of vtkRenderer::GetLights() (counted from 1)";
}

int SceneLights::Set(shared::VsMonteCarloParams& params, vtkRenderer* renderer, bool withAutomaticHeadlight,
  uint32_t* followsCamera, std::vector<int>* leftOutPositions)
{
  params.lightCount = 0u;
  if (followsCamera)
  {
    *followsCamera = 0u;
  }
  vtkLightCollection* lights = renderer ? renderer->GetLights() : nullptr;
  vtkCamera* camera = renderer ? renderer->GetActiveCamera() : nullptr;
  if (!lights || !camera)
  {
    return 0;
  }
  int leftOut = 0, at = -1;
  lights->InitTraversal();
  for (vtkLight* light = lights->GetNextItem(); light; light = lights->GetNextItem())
  {
    ++at;
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0 || (!withAutomaticHeadlight && IsAutomaticHeadlight(light)))
    {
      continue;
    }
    if (params.lightCount >= shared::VS_MAX_SCENE_LIGHTS)
    {
      ++leftOut;
      if (leftOutPositions)
      {
        leftOutPositions->push_back(at);
      }
      continue;
    }
    glm::dvec3 position, focal;
    if (light->LightTypeIsHeadlight())
    {
      // VTK moves a headlight to the camera at every render (vtkRenderer::UpdateLightsGeometryToFollowCamera).
      const double* p = camera->GetPosition();
      const double* f = camera->GetFocalPoint();
      position = glm::dvec3(p[0], p[1], p[2]);
      focal = glm::dvec3(f[0], f[1], f[2]);
    }
    else if (light->LightTypeIsCameraLight())
    {
      // Camera coordinates (the camera at the origin looking down -z, y up) through the camera's light
      // transform, as VTK places them.
      vtkMatrix4x4* m = camera->GetCameraLightTransformMatrix();
      const double* p = light->GetPosition();
      const double* f = light->GetFocalPoint();
      double pin[4] = { p[0], p[1], p[2], 1.0 }, fin[4] = { f[0], f[1], f[2], 1.0 }, pout[4], fout[4];
      m->MultiplyPoint(pin, pout);
      m->MultiplyPoint(fin, fout);
      position = glm::dvec3(pout[0], pout[1], pout[2]) / pout[3];
      focal = glm::dvec3(fout[0], fout[1], fout[2]) / fout[3];
    }
    else
    {
      const double* p = light->GetTransformedPosition();
      position = glm::dvec3(p[0], p[1], p[2]);
      const double* f = light->GetTransformedFocalPoint();
      focal = glm::dvec3(f[0], f[1], f[2]);
    }
    const double* c = light->GetDiffuseColor();
    const double* a = light->GetAttenuationValues();
    shared::VsSceneLight l;
    if (SceneLightParams::Make(l, light->GetPositional() != 0, position, focal, light->GetIntensity(),
          glm::dvec3(c[0], c[1], c[2]), light->GetConeAngle(), light->GetExponent(), glm::dvec3(a[0], a[1], a[2])))
    {
      if (followsCamera && (light->LightTypeIsHeadlight() || light->LightTypeIsCameraLight()))
      {
        *followsCamera |= 1u << params.lightCount;
      }
      params.lights[params.lightCount++] = l;
    }
  }
  return leftOut;
}
}
