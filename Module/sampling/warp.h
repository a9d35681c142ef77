/*
 * warp.h — hierarchical sample warping (Clarberg et al., "Wavelet Importance
 * Sampling", SIGGRAPH 2005) down quadtrees over the equal-area octahedral map.
 *
 * A quadtree node holds the (unnormalised, non-negative) weight of its square
 * of texels. To sample, start at a node and repeatedly pick one of its four
 * children in proportion to their weights: first the column (x) by the
 * column sums, then the row (y) within that column. Each choice consumes one
 * coordinate of the uniform sample u by splitting [0,1) in proportion a : b
 * and rescaling u to [0,1) inside the chosen part, so one 2D sample drives the
 * whole descent, and what is left of u at the leaf is uniform within the leaf
 * (uRemapped). The composed map is piecewise linear and monotone, so it keeps
 * the stratification of u. Each level uses about one bit of u per axis more:
 * a 24-bit float sample leaves roughly 24 - depth - log2(1/p) bits at a leaf.
 *
 * Children are ordered x + 2y: child (cx,cy) of node (x,y) at level l is node
 * (2x+cx, 2y+cy) at level l+1, i.e. the quadtree nests exactly like the texels
 * of octahedral maps of resolution 2^l (texel (x,y) of an n x n map covers
 * uv in [x/n,(x+1)/n) x [y/n,(y+1)/n)).
 *
 * Probabilities returned here are discrete (the chance of the chosen texel or
 * leaf); strategies.h turns them into solid-angle pdfs (x texels / 4π).
 *
 * Two kinds of trees:
 *  - Small tabulated maps (n x n, n in {2,4,8,16}, row-major, index y*n + x,
 *    read through VS_MAP, see vs_prelude.h):
 *    the per-scatter-event visibility or visibility x light product. The tree
 *    is built on the fly, lazily: at each level only the four children of the
 *    current node are summed from the texels. prob = value / total.
 *  - The environment importance quadtree ("env mips"), one flat float array:
 *    level l (0 = 1x1 root ... K = finest, 2^l x 2^l nodes, row-major) starts
 *    at (4^l - 1)/3, each node the mean of its 4 children, the leaves the
 *    luminance of the equal-area octahedral environment texels. It is read
 *    through VS_MIPS (vs_prelude.h), like the tabulated maps through VS_MAP:
 *    in C++ the functions take the array as their first argument
 *    (VS_MIPS_PARAM, `const float* mips`); in GLSL they read the shader's
 *    accessor vs_env_mip(index), which the includer defines after the
 *    #include (reading its SSBO). prob = the product of the chosen children's
 *    normalised weights, so it stays exact even if a stored mean is rounded.
 *
 * Robustness: sides of weight 0 are never chosen; the rescaled sample is
 * clamped to [0, VS_ONE_MINUS_EPSILON]; a tree (or subtree) of total weight 0
 * yields prob 0, which callers must treat as "no sample". Weights must be
 * finite and non-negative; tiny weights (1e-30) are fine.
 */
#ifndef VS_WARP_H
#define VS_WARP_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* ------------------------------------------------------- one 2x2 step */

/* The weight of a node = the sum of its children w (order x + 2y), summed
 * column by column, the same way vs_warp_choose_child splits it. */
VS_FUNC float vs_quad_sum(vec4 w)
{
  return (w.x + w.z) + (w.y + w.w);
}

/* The discrete probability of child c among the weights w; 0 if all are 0. */
VS_FUNC float vs_quad_child_prob(vec4 w, uvec2 c)
{
  float total = vs_quad_sum(w);
  return total > 0.0f ? w[int(c.x + 2u * c.y)] / total : 0.0f;
}

/* Split [0,1) in proportion a : b. Returns 0 if u falls in a's part, else 1,
 * and rescales u to [0,1) within that part. A part of weight 0 is never
 * chosen; if both are 0, returns 0 and leaves u as it is. The comparison
 * u (a + b) < a needs no division, so it cannot pick an empty part however
 * the quotient rounds. */
VS_FUNC uint vs_warp_split(float a, float b, VS_INOUT(float) u)
{
  float s = u * (a + b);
  if (s < a || !(b > 0.0f))
  {
    if (a > 0.0f)
    {
      u = min(s / a, VS_ONE_MINUS_EPSILON);
    }
    return 0u;
  }
  u = clamp((s - a) / b, 0.0f, VS_ONE_MINUS_EPSILON);
  return 1u;
}

/* Choose a child of a node with child weights w (order x + 2y): the column by
 * u.x, then the row within the column by u.y; rescales u. */
VS_FUNC uvec2 vs_warp_choose_child(vec4 w, VS_INOUT(vec2) u)
{
  uint cx = vs_warp_split(w.x + w.z, w.y + w.w, u.x);
  uint cy = cx == 0u ? vs_warp_split(w.x, w.z, u.y) : vs_warp_split(w.y, w.w, u.y);
  return uvec2(cx, cy);
}

/* ---------------------------------- tabulated n x n, n in {2,4,8,16} */

#ifndef __cplusplus
/* Defined by the includer: entry n of the invocation's tabulated map (vs_prelude.h). */
float vs_map_value(uint n);
#endif

/* Sum of the size x size block of texels at origin of the n x n map (index y*n + x). */
VS_FUNC float vs_block_sum(VS_MAP_PARAM uint n, uvec2 origin, uint size)
{
  float s = 0.0f;
  for (uint y = origin.y; y < origin.y + size; ++y)
  {
    for (uint x = origin.x; x < origin.x + size; ++x)
    {
      s += VS_MAP(y * n + x);
    }
  }
  return s;
}

/* Weights of the four children (each size x size texels) of node. */
VS_FUNC vec4 vs_children(VS_MAP_PARAM uint n, uvec2 node, uint size)
{
  uvec2 o = node * (2u * size);
  return vec4(vs_block_sum(VS_MAP_ARG n, o, size), vs_block_sum(VS_MAP_ARG n, o + uvec2(size, 0u), size),
    vs_block_sum(VS_MAP_ARG n, o + uvec2(0u, size), size), vs_block_sum(VS_MAP_ARG n, o + uvec2(size), size));
}

/* The total weight, summed exactly as vs_warp sums it. */
VS_FUNC float vs_warp_total(VS_MAP_PARAM uint n)
{
  return vs_quad_sum(vs_children(VS_MAP_ARG n, uvec2(0u), n / 2u));
}

/* The discrete probability vs_warp gives texel t. */
VS_FUNC float vs_warp_prob(VS_MAP_PARAM uint n, uvec2 t)
{
  float total = vs_warp_total(VS_MAP_ARG n);
  return total > 0.0f ? VS_MAP(t.y * n + t.x) / total : 0.0f;
}

/* Warp u down the quadtree of the n x n map (n*n -> ... -> 1). texel: the chosen
 * texel; prob: its discrete probability value/total (0 if the map is all zero);
 * uRemapped: uniform in [0,1)^2 within the texel. */
VS_FUNC void vs_warp(VS_MAP_PARAM uint n, vec2 u, VS_OUT(uvec2) texel, VS_OUT(float) prob, VS_OUT(vec2) uRemapped)
{
  vec4 w = vs_children(VS_MAP_ARG n, uvec2(0u), n / 2u);
  float total = vs_quad_sum(w);
  uvec2 node = vs_warp_choose_child(w, u);
  for (uint size = n / 4u; size > 0u; size /= 2u)
  {
    node = 2u * node + vs_warp_choose_child(vs_children(VS_MAP_ARG n, node, size), u);
  }
  texel = node;
  prob = total > 0.0f ? VS_MAP(node.y * n + node.x) / total : 0.0f;
  uRemapped = u;
}

/* ------------------ tabulated n x n with its sum pyramid (n in {2,4,8,16}) */

/* The map may carry its sum pyramid behind it: the n x n values (index y*n + x), then the
 * (n/2)^2 sums of their 2x2 blocks, and so on up to the total, (4n^2 - 1) / 3 values in all.
 * Made once per map (vs_pyramid_parent), it lets the warp read 4 values per level instead of
 * summing blocks: log2(n) steps instead of ~n^2. Where the size x size level starts: */
VS_FUNC uint vs_pyramid_offset(uint n, uint size)
{
  return 4u * (n * n - size * size) / 3u;
}

/* The four children (size x size level, order x + 2y) of `node` of the size/2 level. */
VS_FUNC vec4 vs_pyramid_children(VS_MAP_PARAM uint n, uint size, uvec2 node)
{
  uint base = vs_pyramid_offset(n, size);
  uint i = base + 2u * node.y * size + 2u * node.x;
  return vec4(VS_MAP(i), VS_MAP(i + 1u), VS_MAP(i + size), VS_MAP(i + size + 1u));
}

/* The value of `node` of the size/2 level: the sum of its children, as vs_quad_sum adds them. */
VS_FUNC float vs_pyramid_parent(VS_MAP_PARAM uint n, uint size, uvec2 node)
{
  return vs_quad_sum(vs_pyramid_children(VS_MAP_ARG n, size, node));
}

/* Warp u down the pyramid: texel, its probability (the product of the child probabilities the
 * descent took, so exactly what it samples with; 0 if the map is all zero) and u remapped into
 * the texel. */
VS_FUNC void vs_warp_pyramid(
  VS_MAP_PARAM uint n, vec2 u, VS_OUT(uvec2) texel, VS_OUT(float) prob, VS_OUT(vec2) uRemapped)
{
  uvec2 node = uvec2(0u);
  prob = 1.0f;
  for (uint size = 2u; size <= n; size *= 2u)
  {
    vec4 w = vs_pyramid_children(VS_MAP_ARG n, size, node);
    uvec2 c = vs_warp_choose_child(w, u);
    prob *= vs_quad_child_prob(w, c);
    node = 2u * node + c;
  }
  texel = node;
  uRemapped = u;
}

/* The probability vs_warp_pyramid gives texel t. */
VS_FUNC float vs_warp_pyramid_prob(VS_MAP_PARAM uint n, uvec2 t)
{
  float prob = 1.0f;
  for (uint size = 2u; size <= n; size *= 2u)
  {
    /* t's ancestor at the size/2 level and its child at the size level on the way to t. */
    uint shift = 0u;
    for (uint m = n / size; m > 1u; m /= 2u)
      shift += 1u;
    uvec2 node = t >> (shift + 1u);
    uvec2 c = (t >> shift) & uvec2(1u);
    prob *= vs_quad_child_prob(vs_pyramid_children(VS_MAP_ARG n, size, node), c);
  }
  return prob;
}

/* ------------------------------------------ environment importance tree */

#ifndef __cplusplus
/* Defined by the includer: entry `index` of the flat env mip array (vs_prelude.h). */
float vs_env_mip(uint index);
#endif

/* Where level l starts in the flat array: 1 + 4 + ... + 4^(l-1). */
VS_FUNC uint vs_env_level_offset(uint level)
{
  return ((1u << (2u * level)) - 1u) / 3u;
}

VS_FUNC float vs_env_node(VS_MIPS_PARAM uint level, uvec2 node)
{
  return VS_MIPS(vs_env_level_offset(level) + (node.y << level) + node.x);
}

/* The four children (order x + 2y) of node at level, read at level + 1. */
VS_FUNC vec4 vs_env_children(VS_MIPS_PARAM uint level, uvec2 node)
{
  uint row = vs_env_level_offset(level + 1u) + ((2u * node.y) << (level + 1u)) + 2u * node.x;
  uint nextRow = row + (1u << (level + 1u));
  return vec4(VS_MIPS(row), VS_MIPS(row + 1u), VS_MIPS(nextRow), VS_MIPS(nextRow + 1u));
}

/* Descend from startNode at startLevel to a leaf at finestLevel (>= startLevel).
 * leaf: the chosen node at finestLevel; prob: its probability given startNode
 * (0 if the subtree has no weight); uRemapped: uniform within the leaf. */
VS_FUNC void vs_env_descend(VS_MIPS_PARAM uint startLevel, uvec2 startNode, uint finestLevel, vec2 u,
  VS_OUT(uvec2) leaf, VS_OUT(float) prob, VS_OUT(vec2) uRemapped)
{
  uvec2 node = startNode;
  prob = 1.0f;
  for (uint level = startLevel; level < finestLevel; ++level)
  {
    vec4 w = vs_env_children(VS_MIPS_ARG level, node);
    uvec2 c = vs_warp_choose_child(w, u);
    prob *= vs_quad_child_prob(w, c);
    node = 2u * node + c;
  }
  leaf = node;
  uRemapped = u;
}

/* The probability vs_env_descend gives `leaf` (a node at finestLevel) when
 * started at startNode; 0 outside startNode's subtree. Bit-identical to the
 * prob the descent returns. */
VS_FUNC float vs_env_leaf_prob(VS_MIPS_PARAM uint startLevel, uvec2 startNode, uint finestLevel, uvec2 leaf)
{
  if (any(notEqual(leaf >> (finestLevel - startLevel), startNode)))
  {
    return 0.0f;
  }
  float prob = 1.0f;
  for (uint level = startLevel; level < finestLevel; ++level)
  {
    uvec2 node = leaf >> (finestLevel - level);
    uvec2 c = (leaf >> (finestLevel - level - 1u)) & uvec2(1u);
    prob *= vs_quad_child_prob(vs_env_children(VS_MIPS_ARG level, node), c);
  }
  return prob;
}

VS_NAMESPACE_END

#endif
