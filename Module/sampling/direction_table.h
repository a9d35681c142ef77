/*
 * direction_table.h — the grid strategies' direction maps, made once per visibility cell instead of
 * once per scatter event.
 *
 * At a scatter point the grid strategies warp a D x D map (visibility + ε, times the environment's
 * importance at level log2 D for Combined and TwoStep: strategies.h). Building it there costs D²
 * visibility reads, D² importance reads and its sum pyramid (warp.h) for every scatter event, the
 * larger part of TwoStep's cost per sample. The map depends only on the cell (and the grid and the
 * environment), so a table holds, per cell, the quadtree of every map as it is descended: for each
 * of the (D² - 1) / 3 inner nodes (levels 0 .. log2 D - 1, level l's 4^l nodes row-major from
 * vs_env_level_offset(l)) its four children's shares of the node in 16 bits each (order x + 2y),
 * two uints per node. A descent then reads 2 log2 D uints.
 *
 * The table is the pdf: sampling and vs_warp_table_prob read the same bytes, so the estimator
 * stays unbiased whatever the rounding (8 bits were measured too coarse: a sky texel beside the sun
 * got up to 2.5 times its share), as long as a child of positive weight keeps a positive
 * share. vs_table_pack rounds to the nearest 1/65535 of the node but never a positive weight to 0.
 * The shares are normalised by their stored sum at each level, so they need not add to 255.
 * A table made from an earlier grid is still a valid pdf (ε > 0 keeps every direction of the
 * environment possible); one made from another environment is not (its zeros may be where the
 * new environment has light): the host rebuilds it for a new environment before it is read.
 */
#ifndef VS_DIRECTION_TABLE_H
#define VS_DIRECTION_TABLE_H
#include "warp.h"

VS_NAMESPACE_BEGIN

/* The table pass's push constants (direction_table.glsl; vsDirectionTable), std430 as in C++. */
struct VsDirectionTablePush
{
  uvec3 cells;   /* visibility cells per axis */
  float epsilon; /* added to the visibility in the map (the strategies' epsilon) */
};

#ifndef __cplusplus
/* Defined by the includer: entry i of the table (its storage buffer). */
uint vs_table_value(uint i);
#endif

/* Inner nodes of a D x D map's quadtree: 1 + 4 + ... + (D/2)^2 (two uints each). */
VS_FUNC uint vs_table_nodes(uint D)
{
  return (D * D - 1u) / 3u;
}

/* One child's share of a node of weight total, in 1/65535: rounded to nearest, at least 1 when
 * the child has weight. */
VS_FUNC uint vs_table_share(float w, float total)
{
  if (!(w > 0.0f))
  {
    return 0u;
  }
  return uint(clamp(floor(65535.0f * (w / total) + 0.5f), 1.0f, 65535.0f));
}

/* The four children's weights w (order x + 2y, finite, >= 0) as one node of two uints: children 0
 * and 1 in the first (low 16 bits: child 0), 2 and 3 in the second; 0 when all are 0. */
VS_FUNC uvec2 vs_table_pack(vec4 w)
{
  float total = vs_quad_sum(w);
  if (!(total > 0.0f))
  {
    return uvec2(0u);
  }
  return uvec2(vs_table_share(w.x, total) | (vs_table_share(w.y, total) << 16u),
    vs_table_share(w.z, total) | (vs_table_share(w.w, total) << 16u));
}

/* The four shares of a node as weights (0 .. 65535 each). */
VS_FUNC vec4 vs_table_unpack(uvec2 node)
{
  return vec4(float(node.x & 65535u), float(node.x >> 16u), float(node.y & 65535u), float(node.y >> 16u));
}

/* Node i of the cell whose table starts at `base` (uints). */
VS_FUNC vec4 vs_table_children(VS_TABLE_PARAM uint base, uint i)
{
  return vs_table_unpack(uvec2(VS_TABLE(base + 2u * i), VS_TABLE(base + 2u * i + 1u)));
}

/* The packed node `node` of level `level` of the D x D map that carries its sum pyramid (warp.h). */
VS_FUNC uvec2 vs_table_node_from_pyramid(VS_MAP_PARAM uint D, uint level, uvec2 node)
{
  return vs_table_pack(vs_pyramid_children(VS_MAP_ARG D, 2u << level, node));
}

/* Warp u down the table of the cell whose nodes start at `base`: texel, its probability (the
 * product of the shares the descent took, normalised per node; 0 if the map is all zero) and u
 * remapped into the texel. */
VS_FUNC void vs_warp_table(
  VS_TABLE_PARAM uint base, uint D, vec2 u, VS_OUT(uvec2) texel, VS_OUT(float) prob, VS_OUT(vec2) uRemapped)
{
  uvec2 node = uvec2(0u);
  prob = 1.0f;
  uint level = 0u;
  for (uint size = 2u; size <= D; size *= 2u)
  {
    vec4 w = vs_table_children(VS_TABLE_ARG base, vs_env_level_offset(level) + (node.y << level) + node.x);
    uvec2 c = vs_warp_choose_child(w, u);
    prob *= vs_quad_child_prob(w, c);
    node = 2u * node + c;
    level += 1u;
  }
  texel = node;
  uRemapped = u;
}

/* The probability vs_warp_table gives texel t of the D x D map. */
VS_FUNC float vs_warp_table_prob(VS_TABLE_PARAM uint base, uint D, uvec2 t)
{
  uint levels = uint(findMSB(D));
  float prob = 1.0f;
  for (uint level = 0u; level < levels; ++level)
  {
    uvec2 node = t >> (levels - level);
    uvec2 c = (t >> (levels - level - 1u)) & uvec2(1u);
    prob *= vs_quad_child_prob(vs_table_children(VS_TABLE_ARG base, vs_env_level_offset(level) + (node.y << level) + node.x), c);
  }
  return prob;
}

VS_NAMESPACE_END

#endif
