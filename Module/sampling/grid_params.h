/*
 * grid_params.h — the visibility grid's shape (std430; shared by the shaders and the host, the
 * layout rule of volume_params.h): cells over the volume's index-space box, D x D directions of
 * the equal-area octahedral map per cell (von Radziewsky et al. 2017).
 */
#ifndef VS_GRID_PARAMS_H
#define VS_GRID_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

struct VsGridParams
{
  vec3 cellSize;     /* index units per visibility cell */
  uint side;         /* directions per side D (0: no grid) */
  uvec3 cells;       /* visibility cells per axis */
  uint unused;
};

VS_NAMESPACE_END

#endif
