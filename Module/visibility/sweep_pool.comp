#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * The pooled extinction volume the sweeps march: texel j = the mean (or, with
 * VS_POOL_MAX, the max) of sigma_t over voxels [j P, j P + P - 1] (clamped to the
 * volume), sigma_t post-classified at the voxels. Optical depth is linear in sigma_t,
 * so the mean keeps a ray's optical depth through a block; only the detail inside a
 * block is lost (the grid shapes the renderer's pdf: that costs variance, not bias).
 * Clip planes are not applied here (the march clips each ray's interval instead).
 * With VS_POOL_FACTOR, sigma_t at a voxel is scaled by the voxel's extinction factor (the gradient
 * opacity, uFactor): the texel pools sigma_t(s) x g at the voxels, the same product the renderer
 * interpolates between them (exact at the voxels; the pooling's loss of detail as above).
 * With VS_POOL_FROM_QUADS the voxels are read from an integer-coded volume's quads (vsDeviceVolume.h: the
 * low byte of texel (x, y, z) is voxel (x, y, z)'s code), the same floats as its float image, which
 * then need not exist.
 * P, max pooling, cropping, the factor and the quads are specialization constants: the block loops
 * unroll, and what is not used is compiled out (lavapipe runs both sides of a branch).
 */
#include "bindings.h"
#include "pool_params.h"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(constant_id = 0) const int VS_POOL_P = 2;
layout(constant_id = 1) const uint VS_POOL_MAX = 0u;
layout(constant_id = 2) const uint VS_POOL_CROP = 0u;
layout(constant_id = 3) const uint VS_POOL_FACTOR = 0u;
layout(constant_id = 4) const uint VS_POOL_FROM_QUADS = 0u;
layout(binding = VS_POOL_VOLUME, r32f) uniform readonly image3D uVolume; /* read without VS_POOL_FROM_QUADS */
layout(binding = VS_POOL_QUADS, r32ui) uniform readonly uimage3D uQuads; /* read with VS_POOL_FROM_QUADS */
#define VS_TF_TEXELS
layout(binding = VS_POOL_TF) uniform samplerBuffer uTF; /* r32f: the table's floats (volume_access.glsl) */
layout(binding = VS_POOL_POOLED, r32f) uniform writeonly image3D uPooled;
layout(binding = VS_POOL_FACTOR_IMAGE, r32f) uniform readonly image3D uFactor; /* read only with VS_POOL_FACTOR */
layout(push_constant) uniform Push { VsPoolPush pc; };

#include "volume_access.glsl"

void main()
{
  ivec3 j = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, int(pc.firstSlice));
  if (any(greaterThanEqual(j, pc.pooled)))
    return;
  ivec3 lo = j * VS_POOL_P;
  ivec3 last = pc.dims - 1;
  if (VS_POOL_CROP == 1u)
    vs_set_cropping(pc.cropLo, pc.cropHi, pc.cropFlags);
  float sum = 0.0, largest = 0.0;
  for (int z = 0; z < VS_POOL_P; ++z)
    for (int y = 0; y < VS_POOL_P; ++y)
      for (int x = 0; x < VS_POOL_P; ++x)
      {
        // Voxels past the volume's end read its last voxel again: the mean counts them with
        // weight 0 (the block's voxels inside the volume only), the max is unchanged.
        ivec3 v = lo + ivec3(x, y, z);
        ivec3 c = min(v, last);
        float s = VS_POOL_FROM_QUADS == 1u ? float(imageLoad(uQuads, c).r & 0xffu) + pc.quadZero : imageLoad(uVolume, c).r;
        float e = vs_classify_extinction(s, pc.tf);
        if (VS_POOL_FACTOR == 1u)
          e *= imageLoad(uFactor, c).r;
        if (VS_POOL_CROP == 1u)
          e = vs_cropped_out(vec3(c)) ? 0.0 : e;
        sum += all(lessThanEqual(v, last)) ? e : 0.0;
        largest = max(largest, e);
      }
  ivec3 n = min(lo + VS_POOL_P, pc.dims) - lo;
  imageStore(uPooled, j, vec4(VS_POOL_MAX == 1u ? largest : sum / float(n.x * n.y * n.z)));
}
