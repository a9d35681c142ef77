#include "vsPropertyChecks.h"
#include "vsSceneLights.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkRenderer.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdio>

namespace vs
{
namespace
{
const char* BlendModeName(int mode)
{
  switch (mode)
  {
    case vtkVolumeMapper::COMPOSITE_BLEND:
      return "COMPOSITE_BLEND";
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      return "MAXIMUM_INTENSITY_BLEND";
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      return "MINIMUM_INTENSITY_BLEND";
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      return "AVERAGE_INTENSITY_BLEND";
    case vtkVolumeMapper::ADDITIVE_BLEND:
      return "ADDITIVE_BLEND";
    case vtkVolumeMapper::ISOSURFACE_BLEND:
      return "ISOSURFACE_BLEND";
    case vtkVolumeMapper::SLICE_BLEND:
      return "SLICE_BLEND";
  }
  return "an unknown blend mode";
}

}

std::vector<std::string> PropertyChecks::Ignored(
  vtkVolumeMapper* mapper, vtkVolumeProperty* property, vtkRenderer* renderer, bool monteCarlo, bool projection)
{
  std::vector<std::string> ignored;
  if (property)
  {
    // The gradient opacity (component 0) is honoured in every mode and pass (vsGradientOpacity.h),
    // except by the projections, where VTK does not apply it either. Per-label ones are not.
    if (property->HasLabelGradientOpacity())
    {
      ignored.push_back("the vtkVolumeProperty's label gradient opacities (SetLabelGradientOpacity) are ignored: "
                        "VisSweep has no label-map mask input; the gradient opacity of the scalars is honoured");
    }
    // Shading is honoured by the emission-absorption composite (Phong, ea_render.comp).
    if (property->GetShade(0) && projection)
    {
      ignored.push_back("vtkVolumeProperty Shade is on, but a projection blend mode (MIP, MinIP, average, additive) "
                        "is not shaded, as in vtkGPUVolumeRayCastMapper: Ambient, Diffuse, Specular and "
                        "SpecularPower are ignored");
    }
    // The Monte Carlo mode honours Shade since issue 38 (hybrid scattering: Diffuse, Specular and
    // SpecularPower shape the surface lobe; Ambient has no counterpart, the environment is the ambient
    // light, docs/reference.md "Surface scattering"): nothing to warn.
  }
  // Settings of vtkGPUVolumeRayCastMapper that mean something else here (issue 38, item 5): said once
  // per change, not at every render of a converging view.
  auto* sweep = vtkVisibilitySweepVolumeMapper::SafeDownCast(mapper);
  if (sweep && monteCarlo && sweep->GetRenderMode() == vtkVisibilitySweepVolumeMapper::MonteCarlo &&
    sweep->GetSampleDistance() > 0.0)
  {
    ignored.push_back("SampleDistance is not a step of the Monte Carlo estimate (delta and ratio tracking are "
                      "exact and need none, unlike vtkGPUVolumeRayCastMapper's ray march): in the MonteCarlo mode "
                      "it is only the step of the preview shown while the view is dragged; it is the step of the "
                      "EmissionAbsorption, Preview and AmbientOcclusion modes and of the projections");
  }
  if (sweep && !sweep->GetAutoAdjustSampleDistances())
  {
    ignored.push_back("AutoAdjustSampleDistances off has no effect: VisSweep lengthens the deterministic modes' "
                      "step threefold while the view is dragged (InteractiveUpdateRate), and the Monte Carlo "
                      "estimate has no step");
  }
  if (monteCarlo && renderer)
  {
    const std::string lights = SceneLights::LeftOutWarning(renderer);
    if (!lights.empty())
    {
      ignored.push_back(lights);
    }
  }
  // Composite is light transport (or emission-absorption); MIP, MinIP, average and additive are
  // projections, rendered through the emission-absorption path. What is left is not supported.
  const int blend = mapper ? mapper->GetBlendMode() : vtkVolumeMapper::COMPOSITE_BLEND;
  if (blend != vtkVolumeMapper::COMPOSITE_BLEND && blend != vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND &&
    blend != vtkVolumeMapper::MINIMUM_INTENSITY_BLEND && blend != vtkVolumeMapper::AVERAGE_INTENSITY_BLEND &&
    blend != vtkVolumeMapper::ADDITIVE_BLEND)
  {
    ignored.push_back(std::string("the blend mode ") + BlendModeName(blend) +
      " is not supported: VisSweep renders it as COMPOSITE_BLEND (MIP, MinIP, average and additive are "
      "supported)");
  }
  if (renderer && renderer->GetUseDepthPeeling() && renderer->GetUseDepthPeelingForVolumes())
  {
    ignored.push_back("the renderer's UseDepthPeelingForVolumes is not supported: VisSweep draws its volume over the "
                      "depth-peeled translucent geometry, as with it off (the volume is not interleaved with the "
                      "peels; turn it off)");
  }
  return ignored;
}

std::string PropertyChecks::CroppingFlagsName(int flags)
{
  switch (flags)
  {
    case VTK_CROP_SUBVOLUME:
      return "VTK_CROP_SUBVOLUME";
    case VTK_CROP_FENCE:
      return "VTK_CROP_FENCE";
    case VTK_CROP_INVERTED_FENCE:
      return "VTK_CROP_INVERTED_FENCE";
    case VTK_CROP_CROSS:
      return "VTK_CROP_CROSS";
    case VTK_CROP_INVERTED_CROSS:
      return "VTK_CROP_INVERTED_CROSS";
  }
  char hex[32];
  std::snprintf(hex, sizeof(hex), "0x%07x", static_cast<unsigned>(flags));
  return std::string("custom region flags ") + hex;
}

std::vector<std::string> PropertyChecks::NewWarnings(vtkRenderer* renderer, const std::vector<std::string>& current)
{
  this->Active.erase(std::remove_if(this->Active.begin(), this->Active.end(),
                       [](const auto& entry) { return !entry.first; }),
    this->Active.end());
  auto it = std::find_if(
    this->Active.begin(), this->Active.end(), [renderer](const auto& entry) { return entry.first == renderer; });
  if (it == this->Active.end())
  {
    this->Active.emplace_back(renderer, std::vector<std::string>());
    it = this->Active.end() - 1;
  }
  std::vector<std::string> fresh;
  for (const auto& w : current)
  {
    if (std::find(it->second.begin(), it->second.end(), w) == it->second.end())
    {
      fresh.push_back(w);
    }
  }
  it->second = current;
  return fresh;
}

}
