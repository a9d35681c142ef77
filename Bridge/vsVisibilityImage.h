// vsVisibilityImage.h — the device visibility grid as a vtkImageData for VTK
// pipelines: points at the cell centres (aligned with the volume's origin,
// spacing and direction matrix), a D*D-component array "Visibility", the scalar
// "MeanVisibility" (1 - ambient occlusion), and field data with the parameters and
// the direction of each component. Shared by vtkVisibilityGridFilter and the mapper. The light
// volume made from the grid goes beside it as "Irradiance".
#ifndef vsVisibilityImage_h
#define vsVisibilityImage_h

#if !defined(__VTK_WRAP__)
#include "vissweepBridgeModule.h"

class vtkImageData;

namespace vs
{
class LightVolume;
class VisibilityGrid;
struct VolumeGeometry;

/** Fills `out` from `grid`; `physical` is the volume's geometry without any prop matrix. */
VISSWEEPBRIDGE_EXPORT void VisibilityGridToImage(
  const VisibilityGrid& grid, const VolumeGeometry& physical, vtkImageData* out);
/** Adds the point array "Irradiance" (3 components, the light volume's RGB) to `out`, an image
 *  VisibilityGridToImage filled from the grid the light volume was built from. */
VISSWEEPBRIDGE_EXPORT void LightVolumeToImage(const LightVolume& light, vtkImageData* out);
}
#endif

#endif
