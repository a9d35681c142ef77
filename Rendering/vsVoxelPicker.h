// vsVoxelPicker.h — the voxel ids of a vtkHardwareSelector's point and cell id passes. The
// selector reads an id per pixel; for a volume, the natural one is the voxel where the pixel's ray
// becomes part of the volume, which is where its opacity first exceeds the selection threshold
// (3/255, vs::SelectionMask). The device passes return colours only, so the ids are marched on the
// host, per covered pixel: the same extinction as the renderer (sigma_t = -ln(1 - alpha) / unit
// distance x density scale, times the gradient opacity's factor where there is one, the property's
// nearest or trilinear interpolation, NaN voxels empty),
// clipped by the clipping planes and the (cropped) box, and stopped at the opaque depth.
#ifndef vsVoxelPicker_h
#define vsVoxelPicker_h

#include "vsVolumeGeometry.h"

#include "vtkType.h"

#include <glm/glm.hpp>

#include <vector>

class vtkDataArray;
class vtkPiecewiseFunction;

namespace vs
{
class VoxelPicker
{
public:
  struct Volume
  {
    VolumeGeometry Geometry;            // index space <-> world, the (cropped) box
    vtkDataArray* Scalars = nullptr;    // component 0, Dims[0] x Dims[1] x Dims[2] points
    vtkPiecewiseFunction* Opacity = nullptr;
    double UnitDistance = 1.0, DensityScale = 1.0;
    bool Nearest = true;
    std::vector<glm::dvec4> WorldPlanes; // kept where dot(n, x) + w >= 0
    const std::vector<float>* Factor = nullptr; // the extinction factor per voxel (gradient opacity), or none
  };

  /** For each pixel of a width x height viewport (rows bottom-up) whose `covered` flag is set: the
   *  id of the voxel (points: the nearest point; cells: the cell holding the point) where the ray
   *  through the pixel centre first exceeds `threshold` opacity, or -1 when it does not (then the
   *  pixel's id is not written). `depth`: window depth per pixel (1 = nothing opaque). */
  static std::vector<vtkIdType> Ids(const Volume& volume, const glm::dmat4& invViewProj, int width, int height,
    const std::vector<float>& depth, const std::vector<bool>& covered, double threshold, bool cells);
};
}

#endif
