/*
 * majorant_params.h — the push constants of the majorant grid's range pass (majorant_minmax.comp;
 * vsMajorantGrid), shared by the shader and the host (std430, the layout rule of volume_params.h).
 */
#ifndef VS_MAJORANT_PARAMS_H
#define VS_MAJORANT_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* Brick b covers voxels [b B, b B + B] (its corners shared with the next brick). */
struct VsMajorantPush
{
  uvec3 bricks;        /* bricks per axis */
  uint brickSize;      /* B, voxels per side of a brick */
  ivec3 dims;          /* voxels per axis */
  uint unused;
};

VS_NAMESPACE_END

#endif
