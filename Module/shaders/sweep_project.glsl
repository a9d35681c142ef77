/*
 * Visibility sweep, step (4) of von Radziewsky et al. 2017 Fig. 4: project the cell centres of each
 * slice of the chunk along the light onto the start plane and read that slice's
 * (filtered) kernel bilinearly; store into the visibility grid, an image of
 * (cells.x * D, cells.y * D, cells.z) texels: cell c holds its D x D directions as a tile.
 * Included by sweep_project_{r8,r16,r32f}.comp, which define VS_VIS_FORMAT: a store to an
 * image of known format (on lavapipe, measured no faster than a format-less store; kept so
 * the sweeps do not need shaderStorageImageWriteWithoutFormat for the grid).
 */
#include "sweep_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(std430, binding = 0) readonly buffer Globals { VsSweepGlobals G; };
layout(std430, binding = 1) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = 2) readonly buffer Stack { float uStack[]; };
layout(binding = 3, VS_VIS_FORMAT) uniform writeonly image3D uVisibility;
layout(push_constant) uniform Push { uint firstSlice; uint count; uint firstDirection; } pc;

/* Kernel texel (x, y) of a kernel of n.x x n.y rays starting at `base`, clamped to its edge. */
float kernel_at(uvec2 n, uint base, int x, int y)
{
  x = clamp(x, 0, int(n.x) - 1);
  y = clamp(y, 0, int(n.y) - 1);
  return uStack[base + uint(y) * n.x + uint(x)];
}

/* One invocation per cell column (a, b) of one direction: it walks the chunk's slices, so the
 * direction's parameters are loaded once per column, not once per cell. */
void main()
{
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z];
  uint k = D.axes.x, a = D.axes.y, b = D.axes.z;
  uvec2 cab = gl_GlobalInvocationID.xy;
  if (cab.x >= G.grid[a] || cab.y >= G.grid[b])
    return;
  uvec2 n = D.kernel.xy;
  uint rays = n.x * n.y;
  uint dir = D.kernel.w;
  uint side = G.grid.w;
  uvec3 cell;
  cell[a] = cab.x;
  cell[b] = cab.y;
  for (uint s = 0u; s < pc.count; ++s)
  {
    uint slice = pc.firstSlice + s;
    if (slice >= G.grid[k])
      break;
    cell[k] = D.kernel.z == 1u ? G.grid[k] - 1u - slice : slice;
    vec3 p = G.boxMin.xyz + (vec3(cell) + 0.5) * G.cellSize.xyz;
    float t = (p[k] - D.planeOrigin[k]) / D.travel[k];
    vec3 q = p - t * D.travel.xyz;
    float u = (q[a] - D.planeOrigin[a]) / D.kernelStep.x;
    float v = (q[b] - D.planeOrigin[b]) / D.kernelStep.y;
    int x0 = int(floor(u)), y0 = int(floor(v));
    float fx = u - float(x0), fy = v - float(y0);
    uint base = D.axes.w * pc.count + s * rays;
    float V = mix(mix(kernel_at(n, base, x0, y0), kernel_at(n, base, x0 + 1, y0), fx),
      mix(kernel_at(n, base, x0, y0 + 1), kernel_at(n, base, x0 + 1, y0 + 1), fx), fy);
    ivec3 texel = ivec3(int(cell.x * side + dir % side), int(cell.y * side + dir / side), int(cell.z));
    imageStore(uVisibility, texel, vec4(clamp(V, 0.0, 1.0)));
  }
}
