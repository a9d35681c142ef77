#include "vsAccumulationSignature.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <glm/glm.hpp>

namespace vs
{
// Equal up to rounding: VTK recomputes the camera matrices on some passes (e.g. while
// vtkWindowToImageFilter grabs the window) with last-bit differences that are no change.
bool AccumulationSignature::NearlyEqual(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (std::abs(a[i] - b[i]) > 1e-6 * std::max({ 1.0, std::abs(a[i]), std::abs(b[i]) }))
    {
      return false;
    }
  }
  return true;
}

// Every value of the render parameters, integers by value: reinterpreting them as floats
// made small integers (the strategy, the cell mode) denormals that NearlyEqual took for 0,
// so switching Uniform -> Environment kept accumulating into the old image.
std::vector<double> AccumulationSignature::Of(const vs::shared::VsMonteCarloParams& p)
{
  // Not in the signature: directionSources, which MonteCarloPass sets from the grid as it fills in
  // (samples of every stage of the grid are averaged; VisibilityGridUpdater).
  static_assert(sizeof(vs::shared::VsMonteCarloParams) == sizeof(vs::shared::VsCameraParams) +
        sizeof(vs::shared::VsVolumeParams) + sizeof(vs::shared::VsGridParams) + 5 * 16 +
        vs::shared::VS_MAX_RENDER_DIRECTIONS * 4 + 2 * 16 /* issue 38: surface */ +
        16 + vs::shared::VS_MAX_SCENE_LIGHTS * 64 /* issue 38: lights */,
    "a member was added to VsMonteCarloParams: add it to the signature");
  static_assert(sizeof(vs::shared::VsVolumeParams) == 64 + 7 * 16 + vs::shared::VS_MAX_CLIP_PLANES * 16,
    "a member was added to VsVolumeParams: add it to the signature");
  static_assert(sizeof(vs::shared::VsCameraParams) == 80 && sizeof(vs::shared::VsGridParams) == 32,
    "a member was added to VsCameraParams or VsGridParams: add it to the signature");
  std::vector<double> s;
  auto add = [&s](std::initializer_list<double> values) { s.insert(s.end(), values); };
  auto addMat = [&s](const glm::mat4& m) { s.insert(s.end(), &m[0][0], &m[0][0] + 16); };
  auto addVec = [&s](const glm::vec3& v) { s.insert(s.end(), { v.x, v.y, v.z }); };
  auto addUint = [&s](const glm::uvec3& v) { s.insert(s.end(), { double(v.x), double(v.y), double(v.z) }); };
  addMat(p.camera.invViewProj);
  add({ double(p.camera.width), double(p.camera.height), double(p.camera.frame), double(p.camera.seed) });
  const vs::shared::VsVolumeParams& v = p.volume;
  addMat(v.worldToIndex);
  addVec(v.boxMin);
  addVec(v.boxMax);
  addVec(v.dims);
  addVec(v.cropLo);
  addVec(v.cropHi);
  addUint(v.majorantBricks);
  add({ double(v.interpolation), double(v.clipPlaneCount), v.quadZero, double(v.cropFlags), v.majorantBrickSize,
    double(v.extinctionFactor), v.tf.scalar0, v.tf.entriesPerUnit, v.tf.entries, v.tf.rangeLevels });
  for (const auto& c : v.clipPlanes)
  {
    add({ c.x, c.y, c.z, c.w });
  }
  addVec(p.grid.cellSize);
  addUint(p.grid.cells);
  add({ double(p.grid.side), double(p.strategy), double(p.samplesPerFrame), double(p.cellMode),
    double(p.environmentLevels), p.visibilityEpsilon, p.environmentIntensity, p.squareScale, p.defensiveWeight,
    p.cellWalkDepth, double(p.shadowRays), double(p.cameraEstimator), double(p.transmittance), double(p.background),
    double(p.controlExtinction), double(p.pixelSampler), double(p.maxEvents), p.anisotropy, double(p.rouletteDepth),
    double(p.mis), double(p.lightEvents) });
  // issue 38: hybrid scattering.
  add({ double(p.surface), p.surfaceBlending, p.surfaceDiffuse, p.surfaceSpecular, p.surfaceRoughness,
    p.gradientScale, p.opacityDistance });
  // issue 38: VTK's lights (a light added, switched, moved or recoloured restarts the accumulation).
  add({ double(p.lightCount) });
  for (uint32_t i = 0; i < p.lightCount && i < vs::shared::VS_MAX_SCENE_LIGHTS; ++i)
  {
    const vs::shared::VsSceneLight& l = p.lights[i];
    addVec(l.position);
    addVec(l.direction);
    addVec(l.irradiance);
    addVec(l.attenuation);
    add({ double(l.kind), l.cosCone, l.exponent });
  }
  return s;
}
}
