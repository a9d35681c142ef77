// vsEmissionAbsorptionFrame.cxx — the emission-absorption pass's and the voxel picker's inputs (see
// vsEmissionAbsorptionFrame.h).
#include "vsEmissionAbsorptionFrame.h"

#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsTransferFunctionTable.h"
#include "vsVolumeParams.h"
#include "vsSceneLights.h"
#include "vsVolumeScene.h"
#include "sampling/interpolation.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkImageData.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

namespace vs
{
static_assert(vs::shared::VS_BLEND_MAXIMUM == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND &&
    vs::shared::VS_BLEND_MINIMUM == vtkVolumeMapper::MINIMUM_INTENSITY_BLEND &&
    vs::shared::VS_BLEND_AVERAGE == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND &&
    vs::shared::VS_BLEND_ADDITIVE == vtkVolumeMapper::ADDITIVE_BLEND,
  "the shaders' blend modes are VTK's values");

bool EmissionAbsorptionFrame::IsProjection(int blendMode)
{
  return blendMode == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND || blendMode == vtkVolumeMapper::MINIMUM_INTENSITY_BLEND ||
    blendMode == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND || blendMode == vtkVolumeMapper::ADDITIVE_BLEND;
}

shared::VsEmissionAbsorptionParams EmissionAbsorptionFrame::Params(vtkVisibilitySweepVolumeMapper* mapper, vtkRenderer* ren,
  vtkVolume* vol, const VolumeGeometry& geometry, const CameraView& view, const VolumeScene& scene, uint32_t frame,
  bool& shade)
{
  const Viewport& vp = view.Port;
  vs::shared::VsEmissionAbsorptionParams p{};
  p.camera.invViewProj = view.InvViewProj;
  p.camera.width = uint32_t(vp.Width);
  p.camera.height = uint32_t(vp.Height);
  p.camera.frame = frame;
  p.camera.seed = static_cast<uint32_t>(mapper->GetSeed());
  p.volume = MakeVolumeParams(geometry, scene.TF(), scene.Interpolation(),
    vs::FrameGeometry::WorldPlanes(mapper->GetClippingPlanes(), geometry));
  const double step = mapper->GetSampleDistance() > 0.0 ? mapper->GetSampleDistance() : 0.5 * geometry.MinSpacing;
  p.step = float(step);
  p.terminationOpacity = 0.995f;
  if (IsProjection(mapper->GetBlendMode()))
  {
    p.blend = uint32_t(mapper->GetBlendMode()); // VS_BLEND_* are VTK's values
    const double lo = std::clamp(mapper->GetAverageIPScalarRange()[0], -3.0e38, 3.0e38);
    const double hi = std::clamp(mapper->GetAverageIPScalarRange()[1], -3.0e38, 3.0e38);
    const double unit = vol && vol->GetProperty() ? vol->GetProperty()->GetScalarOpacityUnitDistance(0) : 1.0;
    p.averageMin = float(lo);
    p.averageMax = float(hi);
    p.opacityUnitDistance = float(std::max(unit, 1e-30));
  }
  // The property's shading (Phong with VTK's headlight, two-sided) in the composite; the
  // projections are not shaded, as in vtkGPUVolumeRayCastMapper.
  vtkVolumeProperty* property = vol ? vol->GetProperty() : nullptr;
  shade = property && property->GetShade(0) && !IsProjection(mapper->GetBlendMode());
  if (shade)
  {
    p.ambient = float(property->GetAmbient(0));
    p.diffuse = float(property->GetDiffuse(0));
    p.specular = float(property->GetSpecular(0));
    p.specularPower = float(property->GetSpecularPower(0));
    double dop[3];
    ren->GetActiveCamera()->GetDirectionOfProjection(dop);
    p.lightDirection = glm::vec3(float(-dop[0]), float(-dop[1]), float(-dop[2]));
    p.lightIntensity = 1.0f;
    // Issue 38: the renderer's switched-on lights, its automatic headlight included, as VTK's GPU mapper
    // shades with them (ea_render.comp shade); none (a renderer without lights): the headlight above.
    vs::shared::VsMonteCarloParams lights{};
    vs::SceneLights::Set(lights, ren, true);
    p.lightCount = lights.lightCount;
    std::copy(lights.lights, lights.lights + lights.lightCount, p.lights);
    // VTK's GPU mapper shades a lone headlight with ambient x colour (its lighting complexity 1), any other
    // lights with ambient x the sum of their ambient colours x intensities (vtkLight's default ambient colour
    // is black).
    int on = 0, headlights = 0;
    glm::vec3 ambientLight(0.0f);
    vtkLightCollection* collection = ren->GetLights();
    collection->InitTraversal();
    for (vtkLight* light = collection->GetNextItem(); light; light = collection->GetNextItem())
    {
      if (light->GetSwitch() && light->GetIntensity() > 0.0)
      {
        ++on;
        headlights += light->LightTypeIsHeadlight() ? 1 : 0;
        const double* a = light->GetAmbientColor();
        ambientLight += glm::vec3(float(a[0]), float(a[1]), float(a[2])) * float(light->GetIntensity());
      }
    }
    if (lights.lightCount > 0 && !(on == 1 && headlights == 1))
    {
      p.ambientFromLights = 1u;
      p.ambientLightR = ambientLight.r;
      p.ambientLightG = ambientLight.g;
      p.ambientLightB = ambientLight.b;
    }
  }
  return p;
}

VoxelPicker::Volume EmissionAbsorptionFrame::PickerVolume(vtkVisibilitySweepVolumeMapper* mapper, vtkVolume* vol,
  const VolumeScene& scene)
{
  vs::VoxelPicker::Volume v;
  v.Geometry = vs::FrameGeometry::CroppedGeometry(mapper, scene.Geometry());
  int cellFlag = 0;
  v.Scalars = vtkAbstractMapper::GetScalars(vtkImageData::SafeDownCast(mapper->GetInput()), mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  vtkVolumeProperty* property = vol ? vol->GetProperty() : nullptr;
  v.Opacity = property ? property->GetScalarOpacity(0) : nullptr;
  v.UnitDistance = property ? property->GetScalarOpacityUnitDistance(0) : 1.0;
  v.DensityScale = mapper->GetDensityScale();
  v.Nearest = scene.Interpolation() == vs::shared::VS_INTERPOLATION_NEAREST;
  v.WorldPlanes = vs::FrameGeometry::WorldPlanes(mapper->GetClippingPlanes(), v.Geometry);
  v.Factor = scene.HasGradientOpacity() ? &scene.HostFactor() : nullptr;
  return v;
}

glm::dmat4 EmissionAbsorptionFrame::PickerInvViewProj(vtkRenderer* ren, const Viewport& vp)
{
  const double aspect = vp.Height > 0 ? double(vp.Width) / double(vp.Height) : 1.0;
  return glm::inverse(vs::FrameGeometry::ToGlm(ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1)));
}
}
