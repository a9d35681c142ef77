/*
 * volume_params.h — the volume as every pass sees it (std430; shared by the shaders and the host):
 * where it lies, its voxels, its transfer function, its majorant bricks, its clip planes and
 * cropping regions. One block, nested in the Monte Carlo, emission-absorption and sweep parameters
 * (mc_params.h, ea_params.h, sweep_params.h), filled on the host by vs::MakeVolumeParams.
 *
 * Index space: continuous voxel coordinates, voxel centres at integers. Rays march in index space
 * with their parameter t in world units (o_i = worldToIndex o, d_i = worldToIndex_linear d for a
 * unit world direction d), so extinction per world unit integrates over t directly.
 *
 * Layout rule of every parameter block here: each 16-byte row is a mat4 column, a vec4, a vec3
 * followed by one 4-byte scalar, or four 4-byte scalars, so std430 and C++ (GLM, 4-byte aligned)
 * place every member at the same offset without padding rules; the host static_asserts the size.
 */
#ifndef VS_VOLUME_PARAMS_H
#define VS_VOLUME_PARAMS_H
#include "interpolation.h"
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The transfer-function table's parameters (vsTransferFunctionTable.h): scalar s reads the table at
 * entry (s - scalar0) * entriesPerUnit, clamped to [0, entries - 1]; the range-maximum table after it
 * has rangeLevels levels (vs_max_extinction). Floats, as the shaders compute with them. */
struct VsTransferFunction
{
  float scalar0;        /* the scalar of entry 0 */
  float entriesPerUnit; /* entries per scalar unit */
  float entries;        /* entries of the table */
  float rangeLevels;    /* levels of the range-maximum table */
};

struct VsVolumeParams
{
  mat4 worldToIndex;      /* world -> index space */
  vec3 boxMin;            /* index-space box of the volume (cropped: the regions' bounding box) */
  uint interpolation;     /* the scalar's reconstruction (interpolation.h: VS_INTERPOLATION_*) */
  vec3 boxMax;
  uint clipPlaneCount;    /* clipPlanes in use */
  vec3 dims;              /* voxels per axis */
  float quadZero;         /* the scalar of code 0 in the volume's 8-bit quads (vsDeviceVolume.h; the
                             Monte Carlo kernel's VS_SPEC_QUADS pipelines; 0 otherwise) */
  vec3 cropLo;            /* the cropping regions (vsVolumeGeometry.h): index-space planes */
  uint cropFlags;         /* the regions' flags (0 = none: the box is all) */
  vec3 cropHi;
  float majorantBrickSize; /* voxels per side of a majorant brick (vsMajorantGrid.h; 0 without) */
  uvec3 majorantBricks;   /* majorant bricks per axis (0 without) */
  uint extinctionFactor;  /* 1: the extinction is scaled by the volume's factor (the gradient opacity);
                             the host's: the pipelines specialise on it (VS_SPEC_FACTOR) */
  VsTransferFunction tf;
  vec4 clipPlanes[VS_MAX_CLIP_PLANES]; /* index space, (n, w): kept where dot(n, x) + w >= 0 */
};

VS_NAMESPACE_END

#endif
