#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Sweep-space filtering (von Radziewsky et al. 2017, Sec. 8): a box filter over the sweeping kernel
 * before projection, separable, with a sliding window whose cost does not depend
 * on its width (an inclusive prefix sum of the line, then differences of its
 * linear interpolant). Width along an axis: the visibility cell projected onto the
 * sweep plane, widened on each side by t_i tan(beta) (Eq. 9). In place on the kernel
 * stack, one invocation per line (row: pass 0, column: pass 1) per slice per direction.
 */
#include "sweep_params.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(std430, binding = 0) readonly buffer Globals { VsSweepGlobals G; };
layout(std430, binding = 1) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = 2) buffer Stack { float uStack[]; };
layout(std430, binding = 3) buffer Prefix { float uPrefix[]; };
layout(push_constant) uniform Push { uint firstSlice; uint count; uint firstDirection; uint pass; } pc;

/* Integral of the piecewise-constant line over [0, u] (texel j covers [j, j+1)). */
float integral(uint base, uint stride, uint n, float u)
{
  u = clamp(u, 0.0, float(n));
  uint j = min(uint(floor(u)), n - 1u);
  float before = j == 0u ? 0.0 : uPrefix[base + (j - 1u) * stride];
  float here = uPrefix[base + j * stride];
  return before + (u - float(j)) * (here - before);
}

void main()
{
  uint s = gl_GlobalInvocationID.y;
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z];
  uint k = D.axes.x;
  uint slice = pc.firstSlice + s;
  if (s >= pc.count || slice >= G.grid[k])
    return;
  bool rows = pc.pass == 0u;
  uint n = rows ? D.kernel.x : D.kernel.y;
  uint lines = rows ? D.kernel.y : D.kernel.x;
  uint line = gl_GlobalInvocationID.x;
  if (line >= lines)
    return;
  uint stride = rows ? 1u : D.kernel.x;
  uint rays = D.kernel.x * D.kernel.y;
  uint base = D.axes.w * pc.count + s * rays + (rows ? line * D.kernel.x : line);

  float t = vs_slice_t(G.boxMin[k], G.cellSize[k], G.grid[k], D.planeOrigin[k], D.travel[k], D.kernel.z == 1u, slice);
  float width = rows ? D.filterSize.x + 2.0 * t * D.filterSize.z : D.filterSize.y + 2.0 * t * D.filterSize.w;
  if (width <= 1.0)
    return;
  float sum = 0.0;
  for (uint j = 0u; j < n; ++j)
  {
    sum += uStack[base + j * stride];
    uPrefix[base + j * stride] = sum;
  }
  float halfWidth = 0.5 * width;
  for (uint j = 0u; j < n; ++j)
  {
    float lo = max(float(j) + 0.5 - halfWidth, 0.0);
    float hi = min(float(j) + 0.5 + halfWidth, float(n));
    uStack[base + j * stride] = (integral(base, stride, n, hi) - integral(base, stride, n, lo)) / (hi - lo);
  }
}
