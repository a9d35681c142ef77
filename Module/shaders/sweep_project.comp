#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Visibility sweep, step (4) of seed 000 Fig. 4: project the cell centres of each
 * slice of the chunk along the light onto the start plane and read that slice's
 * (filtered) kernel bilinearly; store into the visibility grid, an image of
 * (cells.x * D, cells.y * D, cells.z) texels: cell c holds its D x D directions as a tile.
 */
#include "sweep_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(std430, binding = 0) readonly buffer Globals { VsSweepGlobals G; };
layout(std430, binding = 1) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = 2) readonly buffer Stack { float uStack[]; };
layout(binding = 3) uniform writeonly image3D uVisibility; /* format-free write: r8, r16 or r32f */
layout(push_constant) uniform Push { uint firstSlice; uint count; uint firstDirection; } pc;

float kernel_at(VsSweepDirection D, uint base, int x, int y)
{
  x = clamp(x, 0, int(D.kernel.x) - 1);
  y = clamp(y, 0, int(D.kernel.y) - 1);
  return uStack[base + uint(y) * D.kernel.x + uint(x)];
}

void main()
{
  uint s = gl_GlobalInvocationID.z % pc.count;
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z / pc.count];
  uint k = D.axes.x, a = D.axes.y, b = D.axes.z;
  uint slice = pc.firstSlice + s;
  uvec2 cab = gl_GlobalInvocationID.xy;
  if (slice >= G.grid[k] || cab.x >= G.grid[a] || cab.y >= G.grid[b])
    return;
  uvec3 cell;
  cell[k] = D.kernel.z == 1u ? G.grid[k] - 1u - slice : slice;
  cell[a] = cab.x;
  cell[b] = cab.y;
  vec3 p = G.boxMin.xyz + (vec3(cell) + 0.5) * G.cellSize.xyz;
  float t = (p[k] - D.planeOrigin[k]) / D.travel[k];
  vec3 q = p - t * D.travel.xyz;
  float u = (q[a] - D.planeOrigin[a]) / D.kernelStep.x;
  float v = (q[b] - D.planeOrigin[b]) / D.kernelStep.y;
  int x0 = int(floor(u)), y0 = int(floor(v));
  float fx = u - float(x0), fy = v - float(y0);
  uint base = D.axes.w * pc.count + s * D.kernel.x * D.kernel.y;
  float V = mix(mix(kernel_at(D, base, x0, y0), kernel_at(D, base, x0 + 1, y0), fx),
    mix(kernel_at(D, base, x0, y0 + 1), kernel_at(D, base, x0 + 1, y0 + 1), fx), fy);
  uint dir = D.kernel.w;
  uint side = G.grid.w;
  ivec3 texel = ivec3(int(cell.x * side + dir % side), int(cell.y * side + dir / side), int(cell.z));
  imageStore(uVisibility, texel, vec4(clamp(V, 0.0, 1.0)));
}
