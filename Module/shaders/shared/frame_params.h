/*
 * frame_params.h — what a render dispatch needs to know about camera, volume
 * and transfer function, laid out identically in std430 GLSL and C++ (only
 * mat4, vec4 and uvec4 members, so the layouts agree without padding rules).
 */
#ifndef VS_FRAME_PARAMS_H
#define VS_FRAME_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

struct VsFrameParams
{
  mat4 invViewProj;  /* OpenGL NDC (z in [-1,1]) -> world */
  mat4 worldToIndex; /* world -> continuous voxel index (voxel centres at integers) */
  mat4 indexToWorld; /* the inverse */
  vec4 boxMin;       /* index-space box the volume occupies (xyz) */
  vec4 boxMax;
  vec4 dims;         /* voxels per axis (xyz) */
  vec4 tf;           /* x: scalar at LUT entry 0, y: entries per scalar unit, z: LUT entries, w: unused */
  vec4 background;   /* rgb + alpha of the constant background (premultiplied) */
  uvec4 viewport;    /* width, height, frame index, seed */
  vec4 march;        /* x: step (world units), y: early-termination opacity, z,w: unused */
  vec4 clipPlanes[6];/* xyz normal, w offset, world space: kept where dot(n,x)+w >= 0 */
  uvec4 counts;      /* x: clip planes in use, y: the scalar's interpolation (interpolation.h) */
};

VS_NAMESPACE_END

#endif
