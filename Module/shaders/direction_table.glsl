/*
 * direction_table.glsl — builds the grid strategies' direction table (shared/direction_table.h):
 * for every visibility cell, its D x D map (direction_map.glsl, as the render kernel would build it
 * at a scatter point in the cell) and the shares of every inner node of the map's quadtree.
 * One invocation per cell. Included by direction_table_<format>.comp, which defines VS_VIS_FORMAT.
 */
#include "strategies.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(binding = 0, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = 1) readonly buffer EnvMips { float uMips[]; };
layout(std430, binding = 2) writeonly buffer Table { uint uTable[]; };
layout(push_constant) uniform Push
{
  uvec4 cells;  /* xyz: cells per axis, w: D */
  uvec4 params; /* x: strategy, y: epsilon (float bits) */
} pc;

#define VS_COUNT(i)
float vs_env_mip(uint index)
{
  return uMips[index];
}
#include "direction_map.glsl"

void main()
{
  uint i = gl_GlobalInvocationID.x;
  uvec3 cells = pc.cells.xyz;
  if (i >= cells.x * cells.y * cells.z)
    return;
  uvec3 cell = uvec3(i % cells.x, (i / cells.x) % cells.y, i / (cells.x * cells.y));
  uint D = pc.cells.w;
  cell_map(cell, pc.params.x, D, uintBitsToFloat(pc.params.y));
  map_pyramid(D);
  uint base = 2u * vs_table_nodes(D) * i;
  uint levels = vs_log2(D);
  for (uint level = 0u; level < levels; ++level)
  {
    uint n = 1u << level;
    for (uint k = 0u; k < n * n; ++k)
    {
      uvec2 node = vs_table_node_from_pyramid(D, level, uvec2(k % n, k / n));
      uint at = base + 2u * (vs_env_level_offset(level) + k);
      uTable[at] = node.x;
      uTable[at + 1u] = node.y;
    }
  }
}
