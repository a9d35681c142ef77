/*
 * interpolation.h — how the shaders reconstruct the scalar between voxels, shared by the
 * shaders (volume_access.glsl) and the host, which passes the mode in each pass's parameters
 * (volume_params.h VsVolumeParams::interpolation).
 * 0 is linear so that parameters left zero keep the trilinear reconstruction; VTK's own
 * constants are the other way round (VTK_NEAREST_INTERPOLATION = 0), so the host translates.
 */
#ifndef VS_INTERPOLATION_H
#define VS_INTERPOLATION_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

VS_CONST uint VS_INTERPOLATION_LINEAR = 0u;  /* trilinear between the 8 voxels around the point */
VS_CONST uint VS_INTERPOLATION_NEAREST = 1u; /* the nearest voxel (its centre's Voronoi cell, as VTK's GPU mapper) */

VS_NAMESPACE_END

#endif
