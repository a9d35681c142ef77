/*
 * quads_params.h — the push constants of the pass that makes an integer-coded volume's float image
 * from its quads when a pass first reads floats (volume_from_quads.comp; vsDeviceVolume), shared by
 * the shader and the host (std430, the layout rule of volume_params.h).
 */
#ifndef VS_QUADS_PARAMS_H
#define VS_QUADS_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

struct VsQuadsPush
{
  ivec3 dims;     /* voxels per axis */
  float quadZero; /* the scalar of code 0 (DeviceVolume::QuadOffset) */
};

VS_NAMESPACE_END

#endif
