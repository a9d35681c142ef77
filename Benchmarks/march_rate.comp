#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * march_rate.comp — the plainest ray march there is, to measure the rate at which the
 * device reads the volume: parallel rays along pc.dir through the whole index box,
 * one trilinear sample (8 imageLoads) and one classification per step, summed so
 * nothing is optimised away. Each invocation adds its step count to uCount[0].
 * The renderer's kernel rate is compared against this (`vissweep bench overhead`).
 */
#include "volume_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, r32f) uniform readonly image3D uVolume;
layout(std430, binding = 1) readonly buffer TransferFunction { vec4 uTF[]; };
layout(std430, binding = 2) buffer Sums { float uSum[]; };
layout(std430, binding = 3) buffer Count { uint uCount[]; };
layout(push_constant) uniform Push
{
  uvec4 rays;  /* x, y: rays per side */
  vec4 dims;   /* volume dimensions */
  VsTransferFunction tf;
  vec4 dir;    /* xyz: ray direction (index space), w: step in voxels */
} pc;

#include "volume_access.glsl"

void main()
{
  uvec2 id = gl_GlobalInvocationID.xy;
  if (id.x >= pc.rays.x || id.y >= pc.rays.y)
    return;
  ivec3 dims = ivec3(pc.dims.xyz);
  vec3 hi = vec3(dims - 1);
  vec3 d = normalize(pc.dir.xyz);
  vec3 a = abs(d.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(d, a));
  vec3 v = cross(d, u);
  float r = 0.5 * length(hi);
  vec2 s = (vec2(id) + 0.5) / vec2(pc.rays.xy) * 2.0 - 1.0;
  vec3 o = 0.5 * hi + r * (s.x * u + s.y * v) - 2.0 * r * d;
  vec2 t = vs_intersect_box(o, d, vec3(0.0), hi);
  float sum = 0.0;
  uint steps = 0u;
  for (float x = max(t.x, 0.0); x < t.y; x += pc.dir.w)
  {
    sum += vs_classify(vs_sample_scalar(o + x * d, dims), pc.tf).w;
    ++steps;
  }
  uSum[id.y * pc.rays.x + id.x] = sum;
  atomicAdd(uCount[0], steps);
}
