// vsSurfaceScattering.h — the host's side of hybrid scattering (issue 38; the kernel's side is
// surface_scattering.glsl, the math sampling/microfacet.h): whether a render compiles the surface lobe,
// the check of its settings, and the translation of VTK's shading settings into the parameters'
// surface fields (VsMonteCarloParams, the fields after directionSources).
#ifndef vsSurfaceScattering_h
#define vsSurfaceScattering_h

#include "sampling/mc_params.h"
#include "vissweepCoreModule.h"

namespace vs
{
class VISSWEEPCORE_EXPORT SurfaceScattering
{
public:
  /** Whether the render kernel compiles the surface lobe (its specialization constant 16,
   *  VS_SPEC_SURFACE): surface on with a blending below 2 (at 2 no event is a surface event, and the
   *  volumetric kernel renders the same image bit for bit). */
  static bool Enabled(const shared::VsMonteCarloParams& params);

  /** Throws InputError naming the setting, its value and its range: a blending outside [0, 2], a
   *  negative or non-finite weight, a diffuse plus specular weight above 1, a roughness outside
   *  (0, 1], a negative or non-finite gradient scale or opacity distance. Checks nothing when the
   *  surface is off. */
  static void Check(const shared::VsMonteCarloParams& params);

  /** The data's scalar range as the parameters' transfer-function table spans it (the table is
   *  resampled over the data's range: vsVolumeScene.h), (entries - 1) / entriesPerUnit; 0 if none. */
  static double ScalarRange(const shared::VsMonteCarloParams& params);

  /** VTK's settings, as the mapper and the scene file give them. */
  struct Settings
  {
    bool Shade = false;       // vtkVolumeProperty::GetShade: the surface lobe at all
    double Blending = 0.0;    // VolumetricScatteringBlending in [0, 2] (VTK 9.2's; 0 its default)
    double Diffuse = 1.0;     // vtkVolumeProperty's Diffuse, Specular and SpecularPower (VTK's defaults)
    double Specular = 0.0;
    double SpecularPower = 10.0;
  };

  /** Fills the surface fields of params: the lobe's weights and roughness (microfacet.h's mappings),
   *  the gradient's normalisation from the data's scalar range and the mean voxel spacing (|grad s|_n =
   *  |grad s| meanSpacing / (0.25 range), vtkGPUVolumeRayCastMapper's), and the distance that makes the
   *  extinction the transfer function's opacity (unit distance / density scale). */
  static void Set(shared::VsMonteCarloParams& params, const Settings& settings, double scalarRange,
    double meanSpacing, double unitDistance, double densityScale);
};
}

#endif
