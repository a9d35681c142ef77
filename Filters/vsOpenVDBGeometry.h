// vsOpenVDBGeometry.h — where vtkOpenVDBVolumeReader's output image lies: a grid's index-to-world
// transform in the axis-aligned form vtkImageData can hold (origin and spacing; a negative scale
// flips the axis), and the image a time step covers (its active voxels plus padding). Internal to
// VisSweep::Filters (hidden from the wrappers).
#ifndef vsOpenVDBGeometry_h
#define vsOpenVDBGeometry_h

#if !defined(__VTK_WRAP__)
#include "vtkType.h"

#include <openvdb/math/Coord.h>
#include <openvdb/math/Mat4.h>
#include <openvdb/math/Transform.h>

#include <string>

namespace vs
{
/** An index-to-world transform without rotation:
 *  world[a] = Translation[a] + Scale[a] * index[a]. */
struct AxisMap
{
  double Scale[3] = { 1, 1, 1 };
  double Translation[3] = { 0, 0, 0 };
};

/** The axis-aligned form of a grid's transform, or false with the reason. */
bool GetAxisMap(const openvdb::math::Transform& xform, AxisMap& map, std::string& why);

/** Whether two index-to-world matrices are equal (each entry within 1e-12 of the other, relative
 *  to the larger magnitude above 1). */
bool SameTransform(const openvdb::Mat4d& a, const openvdb::Mat4d& b);

/** The output image of a step: the index region it covers and its VTK geometry. */
struct OutputGeometry
{
  openvdb::CoordBBox Region; // inclusive, padding included
  bool Empty = false;        // no active voxels: one voxel at (0,0,0) (+ padding)
  bool Flip[3] = { false, false, false };
  int Extent[6] = { 0, -1, 0, -1, 0, -1 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  vtkIdType Points = 0;
};

/** The image covering index box `box` (empty: no active voxels) plus `padding` voxels on each
 *  side, placed by `map`; false with the reason when it would not fit (more than maxPoints points,
 *  or indices beyond int). */
bool MakeOutputGeometry(const openvdb::CoordBBox& box, const AxisMap& map, int padding,
  vtkIdType maxPoints, OutputGeometry& g, std::string& error);
}
#endif

#endif
