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
  vec4 clipPlanes[VS_MAX_CLIP_PLANES];/* xyz normal, w offset, world space: kept where dot(n,x)+w >= 0 */
  uvec4 counts;      /* x: clip planes in use, y: the scalar's interpolation (interpolation.h), z: blend mode
                        (VS_BLEND_*), w: unused */
  vec4 projection;   /* the projections' (VS_BLEND_MAXIMUM..ADDITIVE): x, y: the average's scalar range
                        (vtkVolumeMapper AverageIPScalarRange), z: the opacity unit distance (opacity
                        alpha = 1 - exp(-sigma_t z)), w: unused */
  vec4 cropLo;       /* the cropping regions (vsVolumeGeometry.h): index-space planes, xyz */
  vec4 cropHi;
  uvec4 crop;        /* x: the regions' flags (0 = none: the box is all), y, z, w: unused */
  vec4 shading;      /* Phong shading of the emission-absorption composite (ea_render.comp with
                        VS_EA_SHADE): x ambient, y diffuse, z specular, w specular power */
  vec4 light;        /* xyz: world direction towards the light (VTK's headlight: against the view
                        direction), w: its intensity */
};

/* Blend modes, VTK's vtkVolumeMapper::BlendModes values. Composite is emission-absorption; the
 * projections follow vtkGPUVolumeRayCastMapper (ea_render.comp). */
VS_CONST uint VS_BLEND_COMPOSITE = 0u;
VS_CONST uint VS_BLEND_MAXIMUM = 1u;
VS_CONST uint VS_BLEND_MINIMUM = 2u;
VS_CONST uint VS_BLEND_AVERAGE = 3u;
VS_CONST uint VS_BLEND_ADDITIVE = 4u;

VS_NAMESPACE_END

#endif
