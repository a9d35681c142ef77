/*
 * camera_params.h — the camera of a render dispatch (std430; shared by the shaders and the host,
 * the layout rule of volume_params.h): the pixel grid and the unprojection of its rays.
 */
#ifndef VS_CAMERA_PARAMS_H
#define VS_CAMERA_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

struct VsCameraParams
{
  mat4 invViewProj; /* OpenGL NDC (z in [-1, 1]) -> world */
  uint width;       /* pixels of the image */
  uint height;
  uint frame;       /* the Monte Carlo pass: the index of this frame's first sample per pixel;
                       the emission-absorption pass: the frame's index (its jitter) */
  uint seed;        /* the user's seed of every random stream */
};

VS_NAMESPACE_END

#endif
