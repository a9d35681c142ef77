// vsFrameGeometry.h — the camera and the volume's placement of a frame as the mapper's passes want
// them: the viewport and the float inverse view-projection (camera values beyond float's range are
// refused naming them), the viewport's check against the device's limits, the world clipping
// planes that cut the volume, and the geometry with VTK's cropping regions applied. Shared by the
// mapper's emission-absorption, selection, Monte Carlo and visibility-grid steps.
#ifndef vsFrameGeometry_h
#define vsFrameGeometry_h

#include "vsVolumeGeometry.h"
#include "vsWindowCompositor.h"

#include <glm/glm.hpp>

#include <vector>

class vtkMatrix4x4;
class vtkPlaneCollection;
class vtkRenderer;
class vtkVolumeMapper;

namespace vs
{
class Context;

// The camera and volume placement as the shaders want them.
struct CameraView
{
  Viewport Port;
  glm::mat4 InvViewProj;
};

class FrameGeometry
{
public:
  /** `m` as a glm matrix (column-major). */
  static glm::dmat4 ToGlm(vtkMatrix4x4* m);
  /** The viewport of `ren` and its camera's inverse view-projection; throws vs::InputError for a
   *  camera that does not fit in float. */
  static CameraView MakeView(vtkRenderer* ren);
  /** Throws when a non-empty viewport exceeds the device's or the host's limits. */
  static void CheckViewport(const Context& context, const Viewport& port);
  /** The planes of `planes` that cut the (cropped) box of `geometry`, (n, w) in world space;
   *  throws vs::InputError for a plane that does not fit in float. */
  static std::vector<glm::dvec4> WorldPlanes(vtkPlaneCollection* planes, const VolumeGeometry& geometry);
  /** `full` with the cropping regions of `mapper` applied (itself when cropping is off). */
  static VolumeGeometry CroppedGeometry(vtkVolumeMapper* mapper, const VolumeGeometry& full);
};
}

#endif
