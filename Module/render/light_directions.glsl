/*
 * light_directions.glsl — the render kernel's light direction at a scatter point: the cell pick and
 * the direction map or table of the grid strategies, then the strategy's warp and its pdf
 * (strategies.h). Included once, by mc_render.glsl.
 */

#ifndef VS_NO_GRID
/* The cell one corner of the 8 around index-space point x, picked with its trilinear weight by the
 * pixel's numbers gCellU. */
uvec3 stochastic_cell(vec3 x)
{
  uvec3 cells = gGridCells;
  vec3 c = clamp((x - gBoxMin) / gCellSize - 0.5, vec3(0.0), vec3(cells - 1u));
  uvec3 c0 = uvec3(floor(c));
  uvec3 c1 = min(c0 + 1u, cells - 1u);
  vec3 f = c - vec3(c0);
  vec3 u = gCellU;
  return uvec3(u.x < f.x ? c1.x : c0.x, u.y < f.y ? c1.y : c0.y, u.z < f.z ? c1.z : c0.z);
}

/* The D x D values the strategy warps at index-space point x (direction_map.glsl), with their sum
 * pyramid: one cell's map (stochastic cell), or the maps of the 8 cells around x interpolated. */
void direction_values(vec3 x, uint strategy, uint D, inout VsRng rng)
{
  uvec3 cells = gGridCells;
  vec3 c = (x - gBoxMin) / gCellSize - 0.5;
  c = clamp(c, vec3(0.0), vec3(cells - 1u));
  uvec3 c0 = uvec3(floor(c));
  uvec3 c1 = min(c0 + 1u, cells - 1u);
  vec3 f = c - vec3(c0);
  uint DD = D * D;
  float epsilon = gEpsilon;
  if (VS_SPEC_CELL_MODE == VS_CELL_STOCHASTIC)
  {
    cell_map(stochastic_cell(x), strategy, D, epsilon);
  }
  else
  {
    for (uint n = 0u; n < DD; ++n)
      gValues[n] = 0.0;
    for (uint k = 0u; k < 8u; ++k)
    {
      uvec3 cell = uvec3((k & 1u) != 0u ? c1.x : c0.x, (k & 2u) != 0u ? c1.y : c0.y, (k & 4u) != 0u ? c1.z : c0.z);
      float w = ((k & 1u) != 0u ? f.x : 1.0 - f.x) * ((k & 2u) != 0u ? f.y : 1.0 - f.y) *
        ((k & 4u) != 0u ? f.z : 1.0 - f.z);
      if (w > 0.0)
        for (uint n = 0u; n < DD; ++n)
          gValues[n] += w * visibility_texel(cell, n, D);
    }
    for (uint n = 0u; n < DD; ++n)
      gValues[n] = map_entry(gValues[n], n, strategy, D, epsilon);
  }
  map_pyramid(D);
}

#endif
/* The direction map at x for the grid strategies (once per scatter point, for all its shadow rays):
 * the stochastic cell's table, or the map built here. */
void prepare_directions(vec3 x, uint strategy, inout VsRng rng)
{
  uint D = gGridSide;
  if (strategy == VS_STRATEGY_ENVIRONMENT || strategy == VS_STRATEGY_UNIFORM || D == 0u)
    return;
#ifndef VS_NO_GRID
  if (VS_SPEC_TABLE != 0u)
  {
    uvec3 cell = stochastic_cell(x);
    gTableBase = 2u * vs_table_nodes(D) * ((cell.z * gGridCells.y + cell.y) * gGridCells.x + cell.x);
  }
  else
    direction_values(x, strategy, D, rng);
#endif
}

/* A direction from the strategy (after prepare_directions at the scatter point) and its pdf. */
vec3 sample_direction(uint strategy, vec2 u, out float pdf)
{
  uint K = gEnvLevels;
  uint D = gGridSide;
  if (strategy == VS_STRATEGY_ENVIRONMENT)
    return vs_sample_environment(K, u, pdf);
  if (strategy == VS_STRATEGY_UNIFORM || D == 0u)
    return vs_sample_uniform(u, pdf);
#ifdef VS_NO_GRID
  return vs_sample_uniform(u, pdf); /* not reached: MonteCarloPass uses this module for the other two only */
#else
  if (VS_SPEC_DEFENSIVE != 0u && strategy == VS_STRATEGY_TWO_STEP)
  {
    float alpha = gMixture;
    if (VS_SPEC_TABLE != 0u)
      return vs_sample_defensive_table(gTableBase, D, K, alpha, u, pdf);
    return vs_sample_defensive_pyramid(D, K, alpha, u, pdf);
  }
  if (VS_SPEC_TABLE != 0u)
    return vs_sample_direction_table(strategy, gTableBase, D, K, u, pdf);
  return vs_sample_direction_pyramid(strategy, D, K, u, pdf);
#endif
}

/* The pdf with which sample_direction (after prepare_directions at the same point) would return
 * direction w: what multiple importance sampling weighs a phase-sampled continuation against. */
float direction_pdf(uint strategy, vec3 w)
{
  uint K = gEnvLevels;
  uint D = gGridSide;
  if (strategy == VS_STRATEGY_ENVIRONMENT)
    return vs_pdf_environment(K, w);
  if (strategy == VS_STRATEGY_UNIFORM || D == 0u)
    return vs_pdf_uniform(w);
#ifdef VS_NO_GRID
  return vs_pdf_uniform(w);
#else
  if (VS_SPEC_DEFENSIVE != 0u && strategy == VS_STRATEGY_TWO_STEP)
  {
    float alpha = gMixture;
    if (VS_SPEC_TABLE != 0u)
      return vs_pdf_defensive_table(gTableBase, D, K, alpha, w);
    return vs_pdf_defensive_pyramid(D, K, alpha, w);
  }
  if (VS_SPEC_TABLE != 0u)
    return vs_pdf_direction_table(strategy, gTableBase, D, K, w);
  return vs_pdf_direction_pyramid(strategy, D, K, w);
#endif
}
