/*
 * strategies.h — the five direction-sampling strategies of the renderer
 * (von Radziewsky et al. 2017, Sec. 7): each a sample
 * function returning a unit direction and its pdf, and a pdf function for an
 * arbitrary direction. pdfs are with respect to solid angle (1/sr).
 *
 * All but Uniform are piecewise constant over texels of the equal-area
 * octahedral map: a texel of an n x n map covers 4π/n² sr, so a texel (or
 * leaf) picked with discrete probability P, and a direction uniform within it
 * (the warp's remapped sample pushed through vs_octa_to_dir, which is uniform
 * in solid angle because the map is equal-area), has pdf P n² / (4π).
 *
 *   Uniform      pdf = 1/(4π).
 *   Environment  full descent of the env quadtree (warp.h) from the root to a
 *                leaf at level K (N = 2^K):  pdf = P(leaf) N²/(4π).
 *   Visibility   warp the D x D visibility values (ε already added):
 *                pdf = P(texel) D²/(4π).
 *   Combined     warp the D x D product values, visibility x env node at level
 *                log2(D) (vs_env_node): pdf = P(texel) D²/(4π).
 *   TwoStep      the Combined texel, then descend the env quadtree inside it
 *                from level log2(D) to K:  pdf = P(texel) P(leaf|texel) N²/(4π).
 *                A texel whose env node is 0 has product 0 and is never picked.
 *
 * The render kernel reads the grid strategies' maps from a per-cell table of their quadtrees
 * (direction_table.h: vs_sample_direction_table), or, where it has none, builds the map with its
 * sum pyramid at the scatter point (vs_sample_direction_pyramid).
 *
 * The tabulated map (VS_MAP, see vs_prelude.h) is the visibility map for Visibility
 * and the product map for Combined and TwoStep; Uniform and Environment ignore it.
 * D x D values, row-major, D in {2,4,8,16} (8 by default). K >= log2(D) for TwoStep. A returned pdf of 0 means "no
 * sample" (all-zero map or environment): the caller must skip the sample.
 *
 * The environment's importance quadtree (warp.h) is read through VS_MIPS, like the map through
 * VS_MAP: in C++ every function that reaches it takes the flat array first (VS_MIPS_PARAM,
 * `const float* mips`); in GLSL the shader's vs_env_mip(i).
 */
#ifndef VS_STRATEGIES_H
#define VS_STRATEGIES_H
#include "octahedral.h"
#include "sphere.h"
#include "warp.h"
#include "direction_table.h"

VS_NAMESPACE_BEGIN

VS_CONST uint VS_STRATEGY_UNIFORM = 0u;
VS_CONST uint VS_STRATEGY_ENVIRONMENT = 1u;
VS_CONST uint VS_STRATEGY_VISIBILITY = 2u;
VS_CONST uint VS_STRATEGY_COMBINED = 3u;
VS_CONST uint VS_STRATEGY_TWO_STEP = 4u;

/* ------------------------------------------------------------- helpers */

/* Solid-angle pdf of a texel of an n x n map chosen with probability prob. */
VS_FUNC float vs_texel_pdf(float prob, uint n)
{
  return prob * (float(n) * float(n) * VS_INV_4PI);
}

/* The direction at position uInTexel in [0,1)^2 inside texel t of an n x n map. */
VS_FUNC vec3 vs_dir_in_texel(uvec2 t, vec2 uInTexel, uint n)
{
  return vs_octa_to_dir((vec2(t) + uInTexel) / float(n));
}

VS_FUNC uint vs_log2(uint n)
{
  return uint(findMSB(n));
}

/* One entry of the Combined/TwoStep product map: the visibility of texel t of
 * the D x D map times the env quadtree node over the same texel. */
VS_FUNC float vs_product_weight(VS_MIPS_PARAM float visibility, uvec2 t, uint D)
{
  return visibility * vs_env_node(VS_MIPS_ARG vs_log2(D), t);
}

/* -------------------------------------------------------------- uniform */

VS_FUNC vec3 vs_sample_uniform(vec2 u, VS_OUT(float) pdf)
{
  pdf = vs_uniform_sphere_pdf();
  return vs_sample_uniform_sphere(u);
}

VS_FUNC float vs_pdf_uniform(vec3 /* dir */)
{
  return vs_uniform_sphere_pdf();
}

/* ---------------------------------------------------------- environment */

/* finestLevel K: the env quadtree's leaves are the 2^K x 2^K texels. */
VS_FUNC vec3 vs_sample_environment(VS_MIPS_PARAM uint finestLevel, vec2 u, VS_OUT(float) pdf)
{
  uvec2 leaf;
  float prob;
  vec2 uLeaf;
  vs_env_descend(VS_MIPS_ARG 0u, uvec2(0u), finestLevel, u, leaf, prob, uLeaf);
  uint n = 1u << finestLevel;
  pdf = vs_texel_pdf(prob, n);
  return vs_dir_in_texel(leaf, uLeaf, n);
}

VS_FUNC float vs_pdf_environment(VS_MIPS_PARAM uint finestLevel, vec3 dir)
{
  uint n = 1u << finestLevel;
  float prob = vs_env_leaf_prob(VS_MIPS_ARG 0u, uvec2(0u), finestLevel, vs_dir_to_texel(dir, n));
  return vs_texel_pdf(prob, n);
}

/* ------------------------------------ tabulated D x D maps (Visibility, Combined) */

VS_FUNC vec3 vs_sample_tabulated(VS_MAP_PARAM uint D, vec2 u, VS_OUT(float) pdf)
{
  uvec2 t;
  float prob;
  vec2 uTexel;
  vs_warp(VS_MAP_ARG D, u, t, prob, uTexel);
  pdf = vs_texel_pdf(prob, D);
  return vs_dir_in_texel(t, uTexel, D);
}

VS_FUNC float vs_pdf_tabulated(VS_MAP_PARAM uint D, vec3 dir)
{
  return vs_texel_pdf(vs_warp_prob(VS_MAP_ARG D, vs_dir_to_texel(dir, D)), D);
}

/* ------------------------------------------------------------- two-step */

/* Second step: from texel t (probability probTexel) of the D x D product map,
 * descend the env quadtree to a leaf at finestLevel. */
VS_FUNC vec3 vs_two_step_descend(
  VS_MIPS_PARAM uvec2 t, float probTexel, vec2 uTexel, uint D, uint finestLevel, VS_OUT(float) pdf)
{
  uvec2 leaf;
  float probLeaf;
  vec2 uLeaf;
  vs_env_descend(VS_MIPS_ARG vs_log2(D), t, finestLevel, uTexel, leaf, probLeaf, uLeaf);
  uint n = 1u << finestLevel;
  pdf = vs_texel_pdf(probTexel * probLeaf, n);
  return vs_dir_in_texel(leaf, uLeaf, n);
}

/* pdf of dir given the probability of its texel in the D x D product map. */
VS_FUNC float vs_two_step_pdf_given_texel_prob(
  VS_MIPS_PARAM float probTexel, uvec2 leaf, uint D, uint finestLevel)
{
  uint level = vs_log2(D);
  uvec2 t = leaf >> (finestLevel - level);
  float probLeaf = vs_env_leaf_prob(VS_MIPS_ARG level, t, finestLevel, leaf);
  return vs_texel_pdf(probTexel * probLeaf, 1u << finestLevel);
}

VS_FUNC vec3 vs_sample_two_step(VS_MIPS_PARAM VS_MAP_PARAM uint D, uint finestLevel, vec2 u, VS_OUT(float) pdf)
{
  uvec2 t;
  float prob;
  vec2 uTexel;
  vs_warp(VS_MAP_ARG D, u, t, prob, uTexel);
  return vs_two_step_descend(VS_MIPS_ARG t, prob, uTexel, D, finestLevel, pdf);
}

VS_FUNC float vs_pdf_two_step(VS_MIPS_PARAM VS_MAP_PARAM uint D, uint finestLevel, vec3 dir)
{
  uvec2 leaf = vs_dir_to_texel(dir, 1u << finestLevel);
  float probTexel = vs_warp_prob(VS_MAP_ARG D, leaf >> (finestLevel - vs_log2(D)));
  return vs_two_step_pdf_given_texel_prob(VS_MIPS_ARG probTexel, leaf, D, finestLevel);
}

/* ---------------------------- the same from a map that carries its sum pyramid (warp.h) */

VS_FUNC vec3 vs_sample_tabulated_pyramid(VS_MAP_PARAM uint D, vec2 u, VS_OUT(float) pdf)
{
  uvec2 t;
  float prob;
  vec2 uTexel;
  vs_warp_pyramid(VS_MAP_ARG D, u, t, prob, uTexel);
  pdf = vs_texel_pdf(prob, D);
  return vs_dir_in_texel(t, uTexel, D);
}

VS_FUNC float vs_pdf_tabulated_pyramid(VS_MAP_PARAM uint D, vec3 dir)
{
  return vs_texel_pdf(vs_warp_pyramid_prob(VS_MAP_ARG D, vs_dir_to_texel(dir, D)), D);
}

VS_FUNC vec3 vs_sample_two_step_pyramid(
  VS_MIPS_PARAM VS_MAP_PARAM uint D, uint finestLevel, vec2 u, VS_OUT(float) pdf)
{
  uvec2 t;
  float prob;
  vec2 uTexel;
  vs_warp_pyramid(VS_MAP_ARG D, u, t, prob, uTexel);
  return vs_two_step_descend(VS_MIPS_ARG t, prob, uTexel, D, finestLevel, pdf);
}

VS_FUNC float vs_pdf_two_step_pyramid(VS_MIPS_PARAM VS_MAP_PARAM uint D, uint finestLevel, vec3 dir)
{
  uvec2 leaf = vs_dir_to_texel(dir, 1u << finestLevel);
  float probTexel = vs_warp_pyramid_prob(VS_MAP_ARG D, leaf >> (finestLevel - vs_log2(D)));
  return vs_two_step_pdf_given_texel_prob(VS_MIPS_ARG probTexel, leaf, D, finestLevel);
}

/* vs_sample_direction for a map with its pyramid (the render kernel's form). */
VS_FUNC vec3 vs_sample_direction_pyramid(
  VS_MIPS_PARAM uint strategy, VS_MAP_PARAM uint D, uint finestLevel, vec2 u, VS_OUT(float) pdf)
{
  if (strategy == VS_STRATEGY_ENVIRONMENT)
  {
    return vs_sample_environment(VS_MIPS_ARG finestLevel, u, pdf);
  }
  if (strategy == VS_STRATEGY_VISIBILITY || strategy == VS_STRATEGY_COMBINED)
  {
    return vs_sample_tabulated_pyramid(VS_MAP_ARG D, u, pdf);
  }
  if (strategy == VS_STRATEGY_TWO_STEP)
  {
    return vs_sample_two_step_pyramid(VS_MIPS_ARG VS_MAP_ARG D, finestLevel, u, pdf);
  }
  return vs_sample_uniform(u, pdf);
}

VS_FUNC float vs_pdf_direction_pyramid(
  VS_MIPS_PARAM uint strategy, VS_MAP_PARAM uint D, uint finestLevel, vec3 dir)
{
  if (strategy == VS_STRATEGY_ENVIRONMENT)
  {
    return vs_pdf_environment(VS_MIPS_ARG finestLevel, dir);
  }
  if (strategy == VS_STRATEGY_VISIBILITY || strategy == VS_STRATEGY_COMBINED)
  {
    return vs_pdf_tabulated_pyramid(VS_MAP_ARG D, dir);
  }
  if (strategy == VS_STRATEGY_TWO_STEP)
  {
    return vs_pdf_two_step_pyramid(VS_MIPS_ARG VS_MAP_ARG D, finestLevel, dir);
  }
  return vs_pdf_uniform(dir);
}

/* ------------------- the same from the cell's precomputed table (direction_table.h) */

VS_FUNC vec3 vs_sample_direction_table(
  VS_MIPS_PARAM uint strategy, VS_TABLE_PARAM uint base, uint D, uint finestLevel, vec2 u, VS_OUT(float) pdf)
{
  if (strategy == VS_STRATEGY_ENVIRONMENT)
  {
    return vs_sample_environment(VS_MIPS_ARG finestLevel, u, pdf);
  }
  if (strategy == VS_STRATEGY_UNIFORM)
  {
    return vs_sample_uniform(u, pdf);
  }
  uvec2 t;
  float prob;
  vec2 uTexel;
  vs_warp_table(VS_TABLE_ARG base, D, u, t, prob, uTexel);
  if (strategy == VS_STRATEGY_TWO_STEP)
  {
    return vs_two_step_descend(VS_MIPS_ARG t, prob, uTexel, D, finestLevel, pdf);
  }
  pdf = vs_texel_pdf(prob, D);
  return vs_dir_in_texel(t, uTexel, D);
}

VS_FUNC float vs_pdf_direction_table(
  VS_MIPS_PARAM uint strategy, VS_TABLE_PARAM uint base, uint D, uint finestLevel, vec3 dir)
{
  if (strategy == VS_STRATEGY_ENVIRONMENT)
  {
    return vs_pdf_environment(VS_MIPS_ARG finestLevel, dir);
  }
  if (strategy == VS_STRATEGY_UNIFORM)
  {
    return vs_pdf_uniform(dir);
  }
  if (strategy == VS_STRATEGY_TWO_STEP)
  {
    uvec2 leaf = vs_dir_to_texel(dir, 1u << finestLevel);
    float probTexel = vs_warp_table_prob(VS_TABLE_ARG base, D, leaf >> (finestLevel - vs_log2(D)));
    return vs_two_step_pdf_given_texel_prob(VS_MIPS_ARG probTexel, leaf, D, finestLevel);
  }
  return vs_texel_pdf(vs_warp_table_prob(VS_TABLE_ARG base, D, vs_dir_to_texel(dir, D)), D);
}

/* -------------------------- defensive TwoStep: one-sample MIS with Environment sampling */

/* With probability alpha an Environment sample, else a TwoStep sample from the grid's map (Hesterberg's
 * defensive mixture). Both descend the environment's quadtree inside the chosen D x D texel alike, so
 * for a direction in leaf l of texel t
 *     pdf = (alpha P_env(t) + (1 - alpha) P_grid(t)) P(l | t) N² / (4π),
 * with P_env(t) the environment's probability of t (its descent from the root to level log2 D) and
 * P_grid(t) the map's. Where the grid is wrong (a lit surface point in a cell the grid thinks dark,
 * a direction not swept yet), the sample's weight stays below 1 / alpha times Environment
 * sampling's. alpha = 0 is TwoStep, 1 is Environment sampling. */

/* The second half of either branch: the descent inside texel t (u remapped into it) and the mixture's pdf. */
VS_FUNC vec3 vs_defensive_finish(VS_MIPS_PARAM uvec2 t, vec2 uTexel, float probGrid, float probEnv, float alpha,
  uint D, uint finestLevel, VS_OUT(float) pdf)
{
  uvec2 leaf;
  float probLeaf;
  vec2 uLeaf;
  vs_env_descend(VS_MIPS_ARG vs_log2(D), t, finestLevel, uTexel, leaf, probLeaf, uLeaf);
  uint n = 1u << finestLevel;
  pdf = vs_texel_pdf((alpha * probEnv + (1.0f - alpha) * probGrid) * probLeaf, n);
  return vs_dir_in_texel(leaf, uLeaf, n);
}

/* Which branch u.x picks (u.x rescaled to [0,1) within it): true for the Environment sample. */
VS_FUNC bool vs_defensive_pick(float alpha, VS_INOUT(vec2) u)
{
  if (u.x < alpha)
  {
    u.x = min(u.x / alpha, VS_ONE_MINUS_EPSILON);
    return true;
  }
  u.x = clamp((u.x - alpha) / (1.0f - alpha), 0.0f, VS_ONE_MINUS_EPSILON);
  return false;
}

/* pdf of dir given its texel's probability under the grid's map. */
VS_FUNC float vs_defensive_pdf_given_grid_prob(
  VS_MIPS_PARAM float probGrid, vec3 dir, float alpha, uint D, uint finestLevel)
{
  uint level = vs_log2(D);
  uvec2 leaf = vs_dir_to_texel(dir, 1u << finestLevel);
  uvec2 t = leaf >> (finestLevel - level);
  float probEnv = vs_env_leaf_prob(VS_MIPS_ARG 0u, uvec2(0u), level, t);
  float probLeaf = vs_env_leaf_prob(VS_MIPS_ARG level, t, finestLevel, leaf);
  return vs_texel_pdf((alpha * probEnv + (1.0f - alpha) * probGrid) * probLeaf, 1u << finestLevel);
}

/* From the cell's direction table (the render kernel's default form). */
VS_FUNC vec3 vs_sample_defensive_table(
  VS_MIPS_PARAM VS_TABLE_PARAM uint base, uint D, uint finestLevel, float alpha, vec2 u, VS_OUT(float) pdf)
{
  uvec2 t;
  float probGrid, probEnv;
  vec2 uTexel;
  if (vs_defensive_pick(alpha, u))
  {
    vs_env_descend(VS_MIPS_ARG 0u, uvec2(0u), vs_log2(D), u, t, probEnv, uTexel);
    probGrid = vs_warp_table_prob(VS_TABLE_ARG base, D, t);
  }
  else
  {
    vs_warp_table(VS_TABLE_ARG base, D, u, t, probGrid, uTexel);
    probEnv = vs_env_leaf_prob(VS_MIPS_ARG 0u, uvec2(0u), vs_log2(D), t);
  }
  return vs_defensive_finish(VS_MIPS_ARG t, uTexel, probGrid, probEnv, alpha, D, finestLevel, pdf);
}

VS_FUNC float vs_pdf_defensive_table(
  VS_MIPS_PARAM VS_TABLE_PARAM uint base, uint D, uint finestLevel, float alpha, vec3 dir)
{
  uvec2 t = vs_dir_to_texel(dir, 1u << finestLevel) >> (finestLevel - vs_log2(D));
  return vs_defensive_pdf_given_grid_prob(
    VS_MIPS_ARG vs_warp_table_prob(VS_TABLE_ARG base, D, t), dir, alpha, D, finestLevel);
}

/* From a map that carries its sum pyramid (the kernel's form without a table). */
VS_FUNC vec3 vs_sample_defensive_pyramid(
  VS_MIPS_PARAM VS_MAP_PARAM uint D, uint finestLevel, float alpha, vec2 u, VS_OUT(float) pdf)
{
  uvec2 t;
  float probGrid, probEnv;
  vec2 uTexel;
  if (vs_defensive_pick(alpha, u))
  {
    vs_env_descend(VS_MIPS_ARG 0u, uvec2(0u), vs_log2(D), u, t, probEnv, uTexel);
    probGrid = vs_warp_pyramid_prob(VS_MAP_ARG D, t);
  }
  else
  {
    vs_warp_pyramid(VS_MAP_ARG D, u, t, probGrid, uTexel);
    probEnv = vs_env_leaf_prob(VS_MIPS_ARG 0u, uvec2(0u), vs_log2(D), t);
  }
  return vs_defensive_finish(VS_MIPS_ARG t, uTexel, probGrid, probEnv, alpha, D, finestLevel, pdf);
}

VS_FUNC float vs_pdf_defensive_pyramid(VS_MIPS_PARAM VS_MAP_PARAM uint D, uint finestLevel, float alpha, vec3 dir)
{
  uvec2 t = vs_dir_to_texel(dir, 1u << finestLevel) >> (finestLevel - vs_log2(D));
  return vs_defensive_pdf_given_grid_prob(
    VS_MIPS_ARG vs_warp_pyramid_prob(VS_MAP_ARG D, t), dir, alpha, D, finestLevel);
}

/* ------------------------------------------------------------ dispatch */

/* Any strategy by its VS_STRATEGY_* id; the map = visibility or product map
 * (Visibility and Combined differ only in what the caller puts into it). */
VS_FUNC vec3 vs_sample_direction(
  VS_MIPS_PARAM uint strategy, VS_MAP_PARAM uint D, uint finestLevel, vec2 u, VS_OUT(float) pdf)
{
  if (strategy == VS_STRATEGY_ENVIRONMENT)
  {
    return vs_sample_environment(VS_MIPS_ARG finestLevel, u, pdf);
  }
  if (strategy == VS_STRATEGY_VISIBILITY || strategy == VS_STRATEGY_COMBINED)
  {
    return vs_sample_tabulated(VS_MAP_ARG D, u, pdf);
  }
  if (strategy == VS_STRATEGY_TWO_STEP)
  {
    return vs_sample_two_step(VS_MIPS_ARG VS_MAP_ARG D, finestLevel, u, pdf);
  }
  return vs_sample_uniform(u, pdf);
}

VS_FUNC float vs_pdf_direction(VS_MIPS_PARAM uint strategy, VS_MAP_PARAM uint D, uint finestLevel, vec3 dir)
{
  if (strategy == VS_STRATEGY_ENVIRONMENT)
  {
    return vs_pdf_environment(VS_MIPS_ARG finestLevel, dir);
  }
  if (strategy == VS_STRATEGY_VISIBILITY || strategy == VS_STRATEGY_COMBINED)
  {
    return vs_pdf_tabulated(VS_MAP_ARG D, dir);
  }
  if (strategy == VS_STRATEGY_TWO_STEP)
  {
    return vs_pdf_two_step(VS_MIPS_ARG VS_MAP_ARG D, finestLevel, dir);
  }
  return vs_pdf_uniform(dir);
}

VS_NAMESPACE_END

#endif
