// vsSelectionMask.h — what a VisSweep volume draws in a vtkHardwareSelector pass (vtkPropPicker,
// vtkRenderer::PickProp, area selections). The selector reads the colours of the window as ids, so
// the volume's radiance drawn there was read as hundreds of ids without a prop (issue 14). As
// vtkOpenGLGPUVolumeRayCastMapper does, the volume draws the selector's prop colour where its
// opacity along the pixel's ray exceeds 3/255 and nothing elsewhere; no accumulator is touched.
#ifndef vsSelectionMask_h
#define vsSelectionMask_h

#include "vtkType.h"

#include <vector>

class vtkHardwareSelector;

namespace vs
{
class SelectionMask
{
public:
  /** The opacity above which a pixel belongs to the volume (vtkOpenGLGPUVolumeRayCastMapper's). */
  static constexpr float Threshold = 3.0f / 255.0f;

  /** The premultiplied image to draw for the selector's current pass over a viewport whose
   *  volume opacity per pixel is the alpha of `rgba` (4 floats a pixel): in the actor and process
   *  passes the selector's prop colour (opaque) where the opacity exceeds Threshold, transparent
   *  elsewhere; in the other passes (composite index, point and cell ids) transparent everywhere. */
  static std::vector<float> Image(vtkHardwareSelector* selector, const std::vector<float>& rgba);

  /** Whether the selector's current pass asks for point or cell ids (vs::VoxelPicker finds them),
   *  and whether for cells. */
  static bool AsksForIds(vtkHardwareSelector* selector);
  static bool AsksForCellIds(vtkHardwareSelector* selector);

  /** The image of an id pass: per pixel (ids, -1 = none) the low or high 24 bits of the id as the
   *  selector's colour, opaque; transparent where there is no id. */
  static std::vector<float> IdImage(vtkHardwareSelector* selector, const std::vector<vtkIdType>& ids);

  /** Pixels of `rgba` above Threshold (for tests and PrintSelf). */
  static long Covered(const std::vector<float>& rgba);
};
}

#endif
