#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Visibility sweep, step (3) of seed 000 Fig. 4 / Eq. 8: every kernel ray of every
 * direction of the batch advances from the previous visibility slice to slice
 * `slice`, multiplying its transmittance by the segment's transmittance.
 */
#include "sweep_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, r32f) uniform readonly image3D uVolume;
layout(std430, binding = 1) readonly buffer TransferFunction { vec4 uTF[]; };
layout(binding = 2, r32f) uniform readonly image3D uMajorant;
layout(std430, binding = 3) readonly buffer Globals { VsSweepGlobals G; };
layout(std430, binding = 4) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = 5) buffer Kernel { float uKernel[]; };
layout(push_constant) uniform Push { uint slice; uint firstDirection; } pc;

#include "sweep_access.glsl"

float slice_t(VsSweepDirection D, uint i)
{
  uint k = D.axes.x;
  float c = vs_slice_coordinate(G, k, i, D.kernel.z == 1u, G.grid[k]);
  return (c - D.planeOrigin[k]) / D.travel[k];
}

void main()
{
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z];
  uvec2 r = gl_GlobalInvocationID.xy;
  if (r.x >= D.kernel.x || r.y >= D.kernel.y || pc.slice >= G.grid[D.axes.x])
    return;
  uint idx = D.axes.w + r.y * D.kernel.x + r.x;
  float V = pc.slice == 0u ? 1.0 : uKernel[idx];
  if (V > G.march.z)
  {
    vec3 o = D.planeOrigin.xyz;
    o[D.axes.y] += float(r.x) * D.kernelStep.x;
    o[D.axes.z] += float(r.y) * D.kernelStep.y;
    vec3 d = D.travel.xyz;
    float t0 = pc.slice == 0u ? 0.0 : slice_t(D, pc.slice - 1u);
    float t1 = slice_t(D, pc.slice);
    vec2 box = vs_intersect_box(o, d, G.boxMin.xyz, G.boxMax.xyz);
    float a = max(t0, box.x), b = min(t1, box.y);
    V *= exp(-vs_optical_depth(o, d, a, b));
  }
  uKernel[idx] = V;
}
