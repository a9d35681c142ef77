// vsGradientOpacity.h — the vtkVolumeProperty's gradient opacity as VisSweep honours it: a factor per voxel,
// g = GO(|grad s|), that scales the extinction (sigma_t(s) x g, VTK's opacity x gradient opacity). The
// gradient is the central difference of the scalars in the data's world units (its spacing; one-sided at the
// volume's faces and next to non-finite voxels), as vtkGPUVolumeRayCastMapper computes it; GO is the
// property's gradient-opacity function of component 0, its values clamped to [0, 1] (so sigma_t x g never
// exceeds sigma_t's cap). The render kernel, the emission-absorption pass and the sweeps interpolate g as
// they do the scalar (InterpolationType); the majorants bound it per brick (vsMajorantGrid.h SetFactor).
// Internal to VisSweep (hidden from the wrappers).
#ifndef vsGradientOpacity_h
#define vsGradientOpacity_h

#if !defined(__VTK_WRAP__)
#include "vissweepBridgeModule.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

class vtkPiecewiseFunction;
class vtkVolumeProperty;

namespace vs
{
/** Whether the property's gradient opacity (component 0) changes anything: set,
 * not disabled, and not 1 everywhere (a function that is not clamped is 0
 * outside its points: effective). */
VISSWEEPBRIDGE_EXPORT bool HasEffectiveGradientOpacity(vtkVolumeProperty* property);

/** What g depends on besides the scalars: the function's points and clamping,
 * and the spacing (empty when the gradient opacity is not effective). Equal
 * signatures give equal factors. */
VISSWEEPBRIDGE_EXPORT std::vector<double> GradientOpacitySignature(
  vtkVolumeProperty* property, const double spacing[3]);

/** The factor per voxel (x fastest): GO(|grad s|) in [0, 1]; 0 at non-finite
 * voxels (no sample reads them: a trilinear footprint or nearest voxel holding
 * one is empty space). GO is read from a table of `entries` samples over [0,
 * largest magnitude], linear between them (as VTK's GPU mapper reads its
 * gradient-opacity texture). */
VISSWEEPBRIDGE_EXPORT std::vector<float> GradientOpacityFactor(const float* scalars, std::array<uint32_t, 3> dims,
  const double spacing[3], vtkPiecewiseFunction* gradientOpacity, size_t entries = 4096);
} // namespace vs
#endif // __VTK_WRAP__

#endif
