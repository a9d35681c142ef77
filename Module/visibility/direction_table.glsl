/*
 * direction_table.glsl — builds the grid strategies' direction table (sampling/direction_table.h):
 * for every visibility cell, the shares of every inner node of its D x D map's quadtree, the map's
 * entries being those the render kernel would warp at a scatter point in the cell (map_entry,
 * direction_map.glsl). One invocation per cell. Included by direction_table_<format>.comp, which
 * defines VS_VIS_FORMAT.
 *
 * D and the map are specialization constants, so every loop has a constant trip count and the
 * node sums stay in registers (a dynamically indexed array of the whole map, as the kernel's map
 * path keeps, made the build several times slower on lavapipe). The light's D x D importance is
 * the same for every cell: the workgroup reads it once into shared memory.
 */
#include "bindings.h"
#include "strategies.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(constant_id = 0) const uint VS_SPEC_D = 8u;   /* directions per side, 2 .. 16 */
layout(constant_id = 1) const uint VS_SPEC_MAP = 3u; /* VS_STRATEGY_VISIBILITY, or _COMBINED: the product */
layout(binding = VS_TABLE_VISIBILITY, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = VS_TABLE_MIPS) readonly buffer EnvMips { float uMips[]; };
layout(std430, binding = VS_TABLE_OUTPUT) writeonly buffer Table { uint uTable[]; };
layout(std430, binding = VS_TABLE_SOURCES) readonly buffer Sources { uint uSources[]; }; /* VisibilityGrid::DirectionSources */
layout(push_constant) uniform Push { VsDirectionTablePush pc; };

#define VS_COUNT(i)
#define VS_DIRECTION_SOURCE(n) uSources[n]
float vs_env_mip(uint index)
{
  return uMips[index];
}
#include "direction_map.glsl"

shared float sLight[256]; /* the light's importance per direction (1 for Visibility's map) */

void write_node(uint base, uint node, vec4 w)
{
  uvec2 packed = vs_table_pack(w);
  uTable[base + 2u * node] = packed.x;
  uTable[base + 2u * node + 1u] = packed.y;
}

void main()
{
  const uint D = VS_SPEC_D;
  const uint levels = D >= 16u ? 4u : D >= 8u ? 3u : D >= 4u ? 2u : 1u;
  for (uint n = gl_LocalInvocationIndex; n < D * D; n += 64u)
    sLight[n] = VS_SPEC_MAP == VS_STRATEGY_VISIBILITY ? 1.0 : vs_env_node(levels, uvec2(n % D, n / D));
  barrier();

  uint i = gl_GlobalInvocationID.x;
  uvec3 cells = pc.cells;
  if (i >= cells.x * cells.y * cells.z)
    return;
  uvec3 cell = uvec3(i % cells.x, (i / cells.x) % cells.y, i / (cells.x * cells.y));
  float epsilon = pc.epsilon;
  uint base = 2u * vs_table_nodes(D) * i;
  /* The inner nodes' weights, level by level (vs_env_level_offset), as the map's sum pyramid has them. */
  float sums[85];
  /* The finest inner level: each node's four children are map entries. */
  const uint side = D / 2u; /* nodes per side of the finest inner level */
  const uint finest = vs_env_level_offset(levels - 1u);
  for (uint k = 0u; k < side * side; ++k)
  {
    uvec2 t = 2u * uvec2(k % side, k / side);
    uint n0 = t.y * D + t.x;
    /* map_entry's arithmetic: (v + epsilon) times the light (times 1 for Visibility: the same bits). */
    vec4 w = vec4((visibility_texel(cell, n0, D) + epsilon) * sLight[n0],
      (visibility_texel(cell, n0 + 1u, D) + epsilon) * sLight[n0 + 1u],
      (visibility_texel(cell, n0 + D, D) + epsilon) * sLight[n0 + D],
      (visibility_texel(cell, n0 + D + 1u, D) + epsilon) * sLight[n0 + D + 1u]);
    write_node(base, finest + k, w);
    sums[finest + k] = vs_quad_sum(w);
  }
  /* Coarser levels: the children are the weights of the level below. */
  for (uint l = 1u; l < levels; ++l)
  {
    uint level = levels - 1u - l;
    uint n = 1u << level;
    uint below = vs_env_level_offset(level + 1u);
    for (uint k = 0u; k < n * n; ++k)
    {
      uint c = below + 2u * (k / n) * (2u * n) + 2u * (k % n);
      vec4 w = vec4(sums[c], sums[c + 1u], sums[c + 2u * n], sums[c + 2u * n + 1u]);
      write_node(base, vs_env_level_offset(level) + k, w);
      sums[vs_env_level_offset(level) + k] = vs_quad_sum(w);
    }
  }
}
