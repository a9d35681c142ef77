// vsVolumeParams.cxx — see vsVolumeParams.h.
#include "vsVolumeParams.h"

#include "vsError.h"
#include "vsMajorantGrid.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeGeometry.h"

#include <cmath>
#include <string>

namespace vs
{
// std430 and C++ agree on every offset when each 16-byte row holds a vec4, a vec3 and one scalar,
// or four scalars (volume_params.h); a member that breaks the rule changes the size.
static_assert(sizeof(shared::VsTransferFunction) == 16, "VsTransferFunction is one 16-byte row");
static_assert(sizeof(shared::VsVolumeParams) == 64 + 7 * 16 + shared::VS_MAX_CLIP_PLANES * 16,
  "VsVolumeParams: rows of 16 bytes (volume_params.h)");

shared::VsVolumeParams MakeVolumeParams(const VolumeGeometry& geometry, const TransferFunctionTable& tf,
  uint32_t interpolation, const std::vector<glm::dvec4>& worldPlanes, const MajorantGrid* majorants)
{
  if (worldPlanes.size() > shared::VS_MAX_CLIP_PLANES)
  {
    throw InputError(std::to_string(worldPlanes.size()) + " clipping planes cut the volume; the passes take at most " +
      std::to_string(shared::VS_MAX_CLIP_PLANES));
  }
  shared::VsVolumeParams v{};
  v.worldToIndex = glm::mat4(geometry.WorldToIndex);
  v.boxMin = geometry.BoxMin;
  v.boxMax = geometry.BoxMax;
  v.dims = glm::vec3(float(geometry.Dims[0]), float(geometry.Dims[1]), float(geometry.Dims[2]));
  v.interpolation = interpolation;
  v.cropLo = geometry.CropLo;
  v.cropHi = geometry.CropHi;
  v.cropFlags = geometry.CropFlags;
  v.tf = tf.Params();
  if (majorants)
  {
    auto b = majorants->Bricks();
    v.majorantBricks = glm::uvec3(b[0], b[1], b[2]);
    v.majorantBrickSize = float(majorants->BrickSize());
  }
  const glm::dmat3 m(geometry.IndexToWorld);
  const glm::dvec3 o(geometry.IndexToWorld[3]);
  for (size_t i = 0; i < worldPlanes.size(); ++i)
  {
    const glm::dvec3 n(worldPlanes[i]);
    const glm::vec4 c(glm::vec3(glm::transpose(m) * n), float(glm::dot(n, o) + worldPlanes[i].w));
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w)))
    {
      throw InputError("clipping plane " + std::to_string(i) + " does not fit in float in the volume's index space");
    }
    v.clipPlanes[i] = c;
  }
  v.clipPlaneCount = uint32_t(worldPlanes.size());
  return v;
}
}
