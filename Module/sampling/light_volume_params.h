/*
 * light_volume_params.h — the parameters of the light volume's build (visibility/light_volume.glsl,
 * visibility/vsLightVolume.cxx): the push-constant block, laid out identically in std430 GLSL and
 * C++. Named scalar fields (4-byte aligned in both), no vec3; the C++ side checks the layout below.
 */
#ifndef VS_LIGHT_VOLUME_PARAMS_H
#define VS_LIGHT_VOLUME_PARAMS_H
#include "vs_prelude.h"
#include "volume_params.h"
#include "scene_lights.h"

VS_NAMESPACE_BEGIN

struct VsLightVolumeParams
{
  uint cellsX; /* visibility cells per axis: the light volume's texels */
  uint cellsY;
  uint cellsZ;
};
/* The grid's D (directions per side) is the shader's specialization constant 0, not a field: its
 * loop over the D x D directions then has a constant trip count (3x faster on lavapipe). */

/* Multiple scattering (vsLightVolume.h): the per-cell albedo's pass (light_volume_albedo.comp), its
 * parameters in a storage buffer (the volume's, as every pass sees them, and the cells). */
struct VsLightAlbedoParams
{
  VsVolumeParams volume; /* volume.boxMin: the grid's origin (index space) */
  vec3 cellSize;         /* index units per cell */
  uint samplesPerAxis;   /* the cell's samples per axis (stratified, fixed: deterministic) */
  uvec3 cells;
  uint lit;              /* 1: add the scene lights' direct light (VS_LIGHTMS_DIRECT) to the first order's
                            emission and light (they scatter into the later orders; the preview lights
                            the first order itself) */
};

/* VTK's lights in the light volume (issue 38, light_volume_lights.comp): per cell and light, the
 * transmittance from the cell's centre towards the light (to the light, or to where the ray leaves the
 * volume), marched through the volume in steps of `step` (world units, at their midpoints: nothing
 * random), and the cell's direct light sum_l T_l E_l (E_l the light's irradiance at the centre,
 * scene_lights.h). A storage buffer. */
struct VsLightSceneParams
{
  VsVolumeParams volume; /* volume.boxMin: the grid's origin (index space) */
  mat4 indexToWorld;     /* the inverse of volume.worldToIndex (the lights are in world space) */
  vec3 cellSize;         /* index units per cell */
  uint lightCount;       /* lights[0 .. lightCount) */
  uvec3 cells;
  float step;            /* the march's step, world units */
  VsSceneLight lights[VS_MAX_SCENE_LIGHTS];
};

/* One order of scattering (light_volume_scatter.glsl): push constants. */
struct VsLightScatterParams
{
  uint cellsX;
  uint cellsY;
  uint cellsZ;
  uint stride;  /* the directions this order marches: texels (stride i + offsetX, stride j + offsetY) of the
                   D x D grid, each standing for stride^2 texels (1: all) */
  uint offsetX;
  uint offsetY;
  float anisotropy;  /* with the shader's specialization constant 1 >= 1 (issue 39): the phase's g, the orders
                       carried on in the similar medium (phase_moments.h vs_similar_*; the order k = 2, whose
                       source is the first order's lobe, is the constant's value 2) */
};

VS_NAMESPACE_END

#ifdef __cplusplus
#include <cstddef>
static_assert(sizeof(vs::shared::VsLightVolumeParams) == 12, "VsLightVolumeParams: 3 uints, as std430 has them");
static_assert(offsetof(vs::shared::VsLightVolumeParams, cellsX) == 0, "VsLightVolumeParams layout");
static_assert(offsetof(vs::shared::VsLightVolumeParams, cellsY) == 4, "VsLightVolumeParams layout");
static_assert(offsetof(vs::shared::VsLightVolumeParams, cellsZ) == 8, "VsLightVolumeParams layout");
static_assert(sizeof(vs::shared::VsLightScatterParams) == 28, "VsLightScatterParams: 6 uints and a float");
static_assert(offsetof(vs::shared::VsLightAlbedoParams, cellSize) == sizeof(vs::shared::VsVolumeParams),
  "VsLightAlbedoParams layout");
static_assert(sizeof(vs::shared::VsLightAlbedoParams) == sizeof(vs::shared::VsVolumeParams) + 32,
  "VsLightAlbedoParams layout");
static_assert(sizeof(vs::shared::VsLightSceneParams) ==
    sizeof(vs::shared::VsVolumeParams) + 64 + 32 + vs::shared::VS_MAX_SCENE_LIGHTS * sizeof(vs::shared::VsSceneLight),
  "VsLightSceneParams: rows of 16 bytes");
static_assert(offsetof(vs::shared::VsLightSceneParams, lights) % 16 == 0, "VsLightSceneParams layout");
#endif

#endif
