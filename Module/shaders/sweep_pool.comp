#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * The pooled extinction volume the sweeps march: texel j = the mean (or, with
 * pc.dims.w = 1, the max) of sigma_t over voxels [j P, j P + P - 1] (clamped to the
 * volume), sigma_t post-classified at the voxels. Optical depth is linear in sigma_t,
 * so the mean keeps a ray's optical depth through a block; only the detail inside a
 * block is lost (the grid shapes the renderer's pdf: that costs variance, not bias).
 * Clip planes are not applied here (the march clips each ray's interval instead).
 */
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, r32f) uniform readonly image3D uVolume;
layout(std430, binding = 1) readonly buffer TransferFunction { vec4 uTF[]; };
layout(binding = 2, r32f) uniform writeonly image3D uPooled;
layout(push_constant) uniform Push
{
  ivec4 dims;   /* voxels per axis, w: 1 = max pooling */
  ivec4 pooled; /* pooled texels per axis, w: P */
  vec4 tf;      /* LUT parameters */
  vec4 cropLo;  /* the cropping regions (vsVolumeGeometry.h): hidden voxels pool as 0 */
  vec4 cropHi;
  uvec4 crop;   /* x: flags */
} pc;

#include "volume_access.glsl"

void main()
{
  ivec3 j = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(j, pc.pooled.xyz)))
    return;
  ivec3 lo = j * pc.pooled.w;
  ivec3 hi = min(lo + pc.pooled.w, pc.dims.xyz);
  vs_set_cropping(pc.cropLo, pc.cropHi, pc.crop.x);
  float sum = 0.0, largest = 0.0;
  for (int z = lo.z; z < hi.z; ++z)
    for (int y = lo.y; y < hi.y; ++y)
      for (int x = lo.x; x < hi.x; ++x)
      {
        float e = vs_cropped_out(vec3(x, y, z)) ? 0.0 : vs_classify(imageLoad(uVolume, ivec3(x, y, z)).r, pc.tf).w;
        sum += e;
        largest = max(largest, e);
      }
  ivec3 n = max(hi - lo, ivec3(1));
  imageStore(uPooled, j, vec4(pc.dims.w == 1 ? largest : sum / float(n.x * n.y * n.z)));
}
