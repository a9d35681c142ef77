// vsEmissionAbsorptionFrame.h — the inputs of the mapper's deterministic passes, made from its
// settings, the volume's property and the camera: the emission-absorption pass's frame parameters
// (placement, transfer function, march, clipping planes, interpolation, cropping, the projections'
// blend mode and range, the property's shading under VTK's headlight), and the host voxel picker's
// volume and camera for a vtkHardwareSelector's id passes. Split from the mapper's
// EmissionAbsorptionImage and RenderSelection. Not wrapped.
#ifndef vsEmissionAbsorptionFrame_h
#define vsEmissionAbsorptionFrame_h

#include "vsFrameGeometry.h"
#include "vsVoxelPicker.h"

#include "sampling/ea_params.h"

#include <glm/glm.hpp>

#include <cstdint>

class vtkRenderer;
class vtkVisibilitySweepVolumeMapper;
class vtkVolume;

namespace vs
{
class VolumeScene;

class EmissionAbsorptionFrame
{
public:
  /** The blend modes rendered as projections through the emission-absorption path. */
  static bool IsProjection(int blendMode);
  /** The emission-absorption pass's parameters for the frame `frame` of `view` over `geometry`;
   *  `shade` tells whether the property's shading applies. */
  static shared::VsEmissionAbsorptionParams Params(vtkVisibilitySweepVolumeMapper* mapper, vtkRenderer* ren, vtkVolume* vol,
    const VolumeGeometry& geometry, const CameraView& view, const VolumeScene& scene, uint32_t frame, bool& shade);
  /** The volume the voxel picker marches: the mapper's input, the property's opacity, the scene's
   *  (cropped) geometry, interpolation and gradient-opacity factor, the clipping planes. */
  static VoxelPicker::Volume PickerVolume(vtkVisibilitySweepVolumeMapper* mapper, vtkVolume* vol, const VolumeScene& scene);
  /** The double inverse view-projection of `ren`'s camera for a viewport of `vp`'s aspect. */
  static glm::dmat4 PickerInvViewProj(vtkRenderer* ren, const Viewport& vp);
};
}

#endif
