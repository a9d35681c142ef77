#include "vsFrameGeometry.h"

#include "vsContext.h"
#include "vsError.h"
#include "vsFloatRange.h"
#include "vsRenderTargetLimits.h"
#include "vsVolumeInput.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolumeMapper.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace vs
{
glm::dmat4 FrameGeometry::ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 g;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      g[c][r] = m->GetElement(r, c);
  return g;
}

// The device gets the camera as a float matrix: a camera value beyond float's range (issue 13,
// item 5) is refused naming it, and so is a matrix whose float form is not finite.
CameraView FrameGeometry::MakeView(vtkRenderer* ren)
{
  CameraView v;
  v.Port = vs::WindowCompositor::GetViewport(ren);
  vtkCamera* camera = ren->GetActiveCamera();
  const std::string problem = vs::FloatRange::CheckCamera(camera);
  if (!problem.empty())
  {
    throw vs::InputError(problem);
  }
  double aspect = v.Port.Height > 0 ? double(v.Port.Width) / double(v.Port.Height) : 1.0;
  v.InvViewProj = glm::mat4(glm::inverse(ToGlm(camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1))));
  const float* m = glm::value_ptr(v.InvViewProj);
  if (!std::all_of(m, m + 16, [](float x) { return std::isfinite(x); }))
  {
    throw vs::InputError("the camera's inverse view-projection matrix does not fit in float (check its position, "
                         "focal point, clipping range and parallel scale)");
  }
  return v;
}

// Before the window's depth is read back and before any pass allocates: the viewport must fit the
// device's limits and the host's memory (issue 13, item 7).
void FrameGeometry::CheckViewport(const vs::Context& context, const vs::Viewport& port)
{
  if (port.Width > 0 && port.Height > 0)
  {
    vs::RenderTargetLimits::Check(context, uint32_t(port.Width), uint32_t(port.Height));
  }
}

// World clipping planes (n, w): kept where dot(n, x) + w >= 0, those that cut the (cropped) box
// of `geometry` (vs::EffectiveClipPlanes: planes that clip nothing are dropped, at most 8 may cut it).
std::vector<glm::dvec4> FrameGeometry::WorldPlanes(vtkPlaneCollection* planes, const vs::VolumeGeometry& geometry)
{
  std::vector<glm::dvec4> out;
  if (!planes)
  {
    return out;
  }
  vtkPlane* plane;
  vtkCollectionSimpleIterator it;
  for (planes->InitTraversal(it); (plane = planes->GetNextPlane(it));)
  {
    // The normal is normalised in double (a normal of 1e300 was an infinity in float, and the
    // plane was ignored); the origin must fit a float, and so must the plane's offset.
    double normal[3], n[3], o[3];
    plane->GetNormal(normal);
    plane->GetOrigin(o);
    const std::string index = std::to_string(out.size());
    if (!vs::FloatRange::Normalize(normal, n))
    {
      throw vs::InputError("clipping plane " + index + " has a zero or non-finite normal");
    }
    for (int i = 0; i < 3; ++i)
    {
      const std::string problem = vs::FloatRange::Check(o[i]);
      if (!problem.empty())
      {
        std::ostringstream os;
        os << "clipping plane " << index << "'s origin (" << "xyz"[i] << " = " << o[i] << ") is " << problem;
        throw vs::InputError(os.str());
      }
    }
    const double w = -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2]);
    if (!vs::FloatRange::Check(w).empty())
    {
      throw vs::InputError("clipping plane " + index + "'s offset from the origin does not fit in float");
    }
    out.emplace_back(n[0], n[1], n[2], w);
  }
  return vs::EffectiveClipPlanes(out, geometry);
}

// The volume's geometry with VTK's cropping regions applied (vs::CropRegions).
vs::VolumeGeometry FrameGeometry::CroppedGeometry(vtkVolumeMapper* mapper, const vs::VolumeGeometry& full)
{
  if (!mapper->GetCropping())
  {
    return full;
  }
  // Any region flags: a union of the 27 boxes; one box (the subvolume, VTK's default) crops the box only.
  return vs::CropRegions(full, vtkImageData::SafeDownCast(mapper->GetInput()), mapper->GetCroppingRegionPlanes(),
    mapper->GetCroppingRegionFlags());
}
}
