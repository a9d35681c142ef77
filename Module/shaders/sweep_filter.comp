#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Sweep-space filtering (seed 000, Sec. 8): a box filter over the sweeping kernel
 * before projection, separable, with a sliding window whose cost does not depend
 * on its width (an inclusive prefix sum per row or column, then differences of the
 * linearly interpolated prefix). Width along an axis: the visibility cell projected
 * on the sweep plane, widened on each side by t_i tan(beta) (Eq. 9).
 * pass 0 (rows, along a): Kernel -> Prefix -> Filtered. pass 1 (columns, along b):
 * Filtered -> Prefix -> Filtered.
 */
#include "sweep_params.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(std430, binding = 0) readonly buffer Globals { VsSweepGlobals G; };
layout(std430, binding = 1) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = 2) readonly buffer Kernel { float uKernel[]; };
layout(std430, binding = 3) buffer Prefix { float uPrefix[]; };
layout(std430, binding = 4) buffer Filtered { float uFiltered[]; };
layout(push_constant) uniform Push { uint slice; uint firstDirection; uint pass; } pc;

/* Integral of the piecewise-constant row over [-0.5, u - 0.5], from the inclusive prefix. */
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
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.y];
  uint k = D.axes.x;
  if (pc.slice >= G.grid[k])
    return;
  bool rows = pc.pass == 0u;
  uint n = rows ? D.kernel.x : D.kernel.y;      /* length of the line */
  uint lines = rows ? D.kernel.y : D.kernel.x;
  uint line = gl_GlobalInvocationID.x;
  if (line >= lines)
    return;
  uint stride = rows ? 1u : D.kernel.x;
  uint base = D.axes.w + (rows ? line * D.kernel.x : line);

  float c = vs_slice_coordinate(G, k, pc.slice, D.kernel.z == 1u, G.grid[k]);
  float t = (c - D.planeOrigin[k]) / D.travel[k];
  float width = rows ? D.filterSize.x + 2.0 * t * D.filterSize.z : D.filterSize.y + 2.0 * t * D.filterSize.w;
  if (width <= 1.0)
  {
    for (uint j = 0u; j < n; ++j)
      uFiltered[base + j * stride] = rows ? uKernel[base + j * stride] : uFiltered[base + j * stride];
    return;
  }
  float sum = 0.0;
  for (uint j = 0u; j < n; ++j)
  {
    sum += rows ? uKernel[base + j * stride] : uFiltered[base + j * stride];
    uPrefix[base + j * stride] = sum;
  }
  float halfWidth = 0.5 * width;
  for (uint j = 0u; j < n; ++j)
  {
    float lo = max(float(j) + 0.5 - halfWidth, 0.0);
    float hi = min(float(j) + 0.5 + halfWidth, float(n));
    uFiltered[base + j * stride] = (integral(base, stride, n, hi) - integral(base, stride, n, lo)) / (hi - lo);
  }
}
