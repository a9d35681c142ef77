/*
 * pool_params.h — the push constants of the pooled extinction volume's two passes
 * (sweep_pool.comp, sweep_pool_occupancy.comp; vsPooledExtinction), shared by the shaders and the
 * host (std430, the layout rule of volume_params.h). P, max pooling, cropping and the factor are
 * the pool pass's specialization constants, not parameters.
 */
#ifndef VS_POOL_PARAMS_H
#define VS_POOL_PARAMS_H
#include "volume_params.h"

VS_NAMESPACE_BEGIN

/* sweep_pool.comp: texel j of the pooled volume pools voxels [j P, j P + P - 1]. */
struct VsPoolPush
{
  ivec3 dims;          /* voxels per axis */
  uint firstSlice;     /* the first pooled slice of this dispatch (slab by slab builds) */
  ivec3 pooled;        /* pooled texels per axis */
  uint cropFlags;      /* the cropping regions (vsVolumeGeometry.h): hidden voxels pool as 0 */
  vec3 cropLo;
  float quadZero;      /* with the quads (VS_POOL_FROM_QUADS): the scalar of code 0 */
  vec3 cropHi;
  uint unused1;
  VsTransferFunction tf;
};

/* sweep_pool_occupancy.comp: brick i of the occupancy map covers pooled texels [i B - 1, (i + 1) B]. */
struct VsOccupancyPush
{
  ivec3 pooled;        /* pooled texels per axis */
  int brickTexels;     /* B, pooled texels per side of a brick */
  ivec3 bricks;        /* bricks per axis */
  uint unused;
};

VS_NAMESPACE_END

#endif
