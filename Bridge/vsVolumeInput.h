// vsVolumeInput.h — what the mapper needs from VTK's side of a volume: checks
// the input and property, and turns them into the core's plain data: float
// scalars, the index <-> world transforms, and the sampled transfer function.
// Internal to VisSweep::Rendering and VisSweep::Filters (not wrapped).
#ifndef vsVolumeInput_h
#define vsVolumeInput_h

// Hidden from VTK's wrappers: plain C++ for the module's own classes.
#if !defined(__VTK_WRAP__)

#include "vissweepBridgeModule.h"
#include "vsHostScalars.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeGeometry.h"

#include <glm/glm.hpp>

#include "vtkType.h"

#include <array>
#include <initializer_list>
#include <string>
#include <vector>

class vtkDataArray;
class vtkObject;
class vtkImageData;
class vtkMatrix4x4;
class vtkVolumeProperty;

namespace vs
{
/** Returns an empty string when `image` can be rendered, else the reason. */
VISSWEEPBRIDGE_EXPORT std::string CheckImage(vtkImageData* image, vtkDataArray* scalars);

/** Returns an empty string when `geometry` (from ComputeGeometry) can be rendered, else the
 *  reason: every index-to-world number finite in float, no axis of zero or sub-1e-30 length
 *  (zero spacing, a singular direction or prop matrix). Axes of one point are fine: they are
 *  one voxel thick (VolumeGeometry's box), so 1 x 1 x 1 and 1 x 1 x N volumes render. */
VISSWEEPBRIDGE_EXPORT std::string CheckGeometry(const VolumeGeometry& geometry);

/** The newest modification time of the given objects (null entries ignored): what decides
 *  whether an error seen again is news (reported once per change, not once per Render()). */
VISSWEEPBRIDGE_EXPORT vtkMTimeType NewestModification(std::initializer_list<vtkObject*> objects);

/** Returns an empty string when `property` can be used, else the reason. */
VISSWEEPBRIDGE_EXPORT std::string CheckProperty(vtkVolumeProperty* property);

/** Voxel centres at array indices; `volumeMatrix` (may be null) is the prop's model matrix. */
VISSWEEPBRIDGE_EXPORT VolumeGeometry ComputeGeometry(vtkImageData* image, vtkMatrix4x4* volumeMatrix);

/** The geometry with its index box cut down to VTK's cropping subvolume: `planes` =
 *  (xmin, xmax, ymin, ymax, zmin, zmax) in data coordinates (vtkVolumeMapper's
 *  CroppingRegionPlanes). For an image with a rotated direction matrix the box is the
 *  index-space bounds of the cropping box. May return an empty box (BoxMin > BoxMax). */
VISSWEEPBRIDGE_EXPORT VolumeGeometry CropGeometry(const VolumeGeometry& geometry, vtkImageData* image,
  const double planes[6]);

/** The geometry cropped to VTK's cropping regions: `planes` as in CropGeometry, `flags` VTK's
 *  CroppingRegionFlags (bit rx + 3 ry + 9 rz of the 27 regions, r = 0 below a plane pair, 1
 *  between, 2 above). The box is cut to the bounding box of the visible regions; when they are not
 *  that one box (VTK_CROP_FENCE, _CROSS, their inversions, any other union) the geometry carries
 *  the planes and flags (VolumeGeometry::CropFlags) and the passes treat points of hidden regions
 *  as empty space. No visible region: an empty box. */
VISSWEEPBRIDGE_EXPORT VolumeGeometry CropRegions(const VolumeGeometry& geometry, vtkImageData* image,
  const double planes[6], int flags);

/** The clipping planes (world (n, w), kept where dot(n, x) + w >= 0) that matter for the volume's
 *  (cropped) index box in `geometry`: a plane that keeps the whole box is dropped (it clips
 *  nothing), a plane that removes the whole box is the only one returned, and an empty box needs
 *  none. Throws InputError when more than VS_MAX_CLIP_PLANES (8, vtkGPUVolumeRayCastMapper's
 *  limit) planes cut the box. */
VISSWEEPBRIDGE_EXPORT std::vector<glm::dvec4> EffectiveClipPlanes(
  const std::vector<glm::dvec4>& planes, const VolumeGeometry& geometry);

/** The scalars as floats, x fastest (component 0). */
VISSWEEPBRIDGE_EXPORT std::vector<float> ScalarsAsFloat(vtkDataArray* scalars);

/** The scalars in place, as the device volume reads them (vsHostScalars.h): a contiguous array of
 *  one component of a type CheckImage accepts; else none (Data null: convert with ScalarsAsFloat).
 *  The device volume then reads each value as ScalarsAsFloat gives it. */
VISSWEEPBRIDGE_EXPORT HostScalars NativeScalars(vtkDataArray* scalars);

/** The transfer function of component 0, sampled over [smin, smax] widened to the TF's points. */
VISSWEEPBRIDGE_EXPORT TransferFunctionSamples SampleTransferFunction(vtkVolumeProperty* property, float smin, float smax,
  double densityScale, size_t entries = 4096);
}

#endif // __VTK_WRAP__

#endif
