// vsVolumeGeometry.h — where a volume sits: its voxel counts, the transforms
// between array index space (voxel centres at integers) and world space, and
// the index-space box it occupies.
#ifndef vsVolumeGeometry_h
#define vsVolumeGeometry_h

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace vs
{
struct VolumeGeometry
{
  std::array<uint32_t, 3> Dims{ { 0, 0, 0 } };
  glm::dmat4 IndexToWorld{ 1.0 };
  glm::dmat4 WorldToIndex{ 1.0 };
  /** Voxel centres, widened to +-0.5 on flat axes (one voxel thick). */
  glm::vec3 BoxMin{ 0.0f }, BoxMax{ 0.0f };
  /** VTK's cropping regions when they are not one box (vtkVolumeMapper CroppingRegionFlags other
   *  than a single region, e.g. VTK_CROP_FENCE): the index-space planes CropLo (x, y, z min) and
   *  CropHi (max) split space into 27 regions, region rx + 3 ry + 9 rz with r = 0 below CropLo, 1
   *  from CropLo on, 2 from CropHi on; a point of a region whose bit of CropFlags is 0 is empty
   *  space (volume_access.glsl vs_cropped_out). CropFlags 0: no regions, the box is all. */
  glm::vec3 CropLo{ 0.0f }, CropHi{ 0.0f };
  uint32_t CropFlags = 0;
  /** Smallest voxel edge in world units. */
  double MinSpacing = 1.0;

  /** World length of one index unit along axis i. */
  double Spacing(int i) const { return glm::length(glm::dvec3(this->IndexToWorld[i])); }

  /** A box of dims voxels with the given spacing and origin, axis-aligned. */
  static VolumeGeometry Axis(std::array<uint32_t, 3> dims, glm::dvec3 spacing = glm::dvec3(1.0),
    glm::dvec3 origin = glm::dvec3(0.0))
  {
    VolumeGeometry g;
    g.Dims = dims;
    g.MinSpacing = 1e300;
    for (int i = 0; i < 3; ++i)
    {
      g.IndexToWorld[i][i] = spacing[i];
      g.IndexToWorld[3][i] = origin[i];
      g.BoxMin[i] = dims[i] > 1 ? 0.0f : -0.5f;
      g.BoxMax[i] = dims[i] > 1 ? float(dims[i] - 1) : 0.5f;
      g.MinSpacing = spacing[i] < g.MinSpacing ? spacing[i] : g.MinSpacing;
    }
    g.WorldToIndex = glm::inverse(g.IndexToWorld);
    return g;
  }
};
}

#endif
