/*
 * direction_map.glsl — the D x D direction map of one visibility cell, as the grid strategies warp
 * it (strategies.h), and its sum pyramid (warp.h). GLSL only; shared by the render kernel
 * (mc_render.glsl, which builds maps at scatter points where it has no table) and the table
 * builder (direction_table.glsl, which reads the same entries for every cell once).
 *
 * The includer declares `uVisibility` (the grid image, VS_VIS_FORMAT), defines VS_COUNT(i)
 * (empty unless it counts reads) and VS_DIRECTION_SOURCE(n) (the direction whose values direction n
 * reads: n, or the nearest swept one while a grid fills in; VisibilityGrid::DirectionSources), and
 * includes strategies.h or warp.h (vs_env_node) before. The grid's entries are read through
 * visibility_texel.glsl.
 */

/* The map of this invocation (D x D <= 256 values) and its sum pyramid, which the strategies read
 * through vs_map_value (vs_prelude.h): one module-scope array, never copied into calls. */
float gValues[344]; /* up to 16 x 16 values and their pyramid: (4 * 256 - 1) / 3 */

float vs_map_value(uint n)
{
  return gValues[n];
}

/* visibility_texel(cell, n, D): one entry of the grid, where its source is. */
#include "visibility_texel.glsl"

/* gValues[n] = entry n of the strategy's map from the visibility v (+ epsilon): v for Visibility,
 * v times the environment's importance at level log2(D) for Combined and TwoStep. */
float map_entry(float v, uint n, uint strategy, uint D, float epsilon)
{
  float e = v + epsilon;
  return strategy == VS_STRATEGY_VISIBILITY ? e : e * vs_env_node(vs_log2(D), uvec2(n % D, n / D));
}

/* The map of one cell, in one pass over its directions. */
void cell_map(uvec3 cell, uint strategy, uint D, float epsilon)
{
  uint DD = D * D;
  for (uint n = 0u; n < DD; ++n)
    gValues[n] = map_entry(visibility_texel(cell, n, D), n, strategy, D, epsilon);
}

/* The sum pyramid behind the map in gValues[0 .. D*D), level by level up to the total. */
void map_pyramid(uint D)
{
  for (uint size = D / 2u; size > 0u; size /= 2u)
  {
    uint base = vs_pyramid_offset(D, size);
    for (uint n = 0u; n < size * size; ++n)
      gValues[base + n] = vs_pyramid_parent(D, 2u * size, uvec2(n % size, n / size));
  }
}
