/*
 * brick_walk.h — the geometry of a ray's walk through the bricks of a majorant grid, written once
 * for the render kernel's majorant segments (mc_render.glsl: brick_at, brick_cube_exit) and the
 * sweeps' empty-space skip (sweep_access.glsl: vs_brick_exit), and tested on the CPU
 * (TestSharedMathBrickWalk.cxx).
 *
 * Bricks are cubes of side `brickSize` in index space, brick b covering [b, b + 1) * brickSize. A
 * walk starts at ray distance t, picks the brick it is in just after t (vs_brick_after), and moves to
 * where the ray leaves that brick, or a cube of bricks around it (vs_brick_cube_exit), at least a
 * shortest step h further (vs_walk_min_step): a sliver of the previous brick shorter than float
 * resolves may go with the next one, and rounding may put a point on the far side of a face, so the
 * walk always moves forward, by at least a float ulp of the point. The segments tile the ray; each lies in the brick (cube) it was picked
 * for, up to that sliver.
 *
 * Why not a 3D DDA (pbrt-v4's DDAMajorantIterator, which steps brick to brick without a floor()):
 * on lavapipe both sides of every branch run, and the DDA's re-derivation of its state after an
 * empty-space jump across a cube of bricks costs as much as the floor() it saves (docs/benchmarks.md).
 */
#ifndef VS_BRICK_WALK_H
#define VS_BRICK_WALK_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The scale of a walk's shortest step for the ray o + t d: the distance in t below which a step may
 * not move the point by one float ulp of its coordinates, (1 + the largest |coordinate| of o) / |d|
 * (about |o| / |d| ulps of t at t = 0; beyond, |t| is the larger term). With 1 / |d| alone, a shadow
 * ray leaving a scatter point at coordinate ~100 crawled across a brick face in 8-10 steps of a
 * fraction of an ulp: 8% more segments than bricks crossed (TestSharedMathBrickWalk). */
VS_FUNC float vs_walk_scale(vec3 o, vec3 d)
{
  vec3 a = abs(o);
  return (1.0f + max(a.x, max(a.y, a.z))) / max(length(d), 1e-20f);
}

/* The shortest step of a walk at ray distance t (scale = vs_walk_scale): 2e-6 of |t| or of the
 * scale, whichever is larger (float keeps about 7 digits: some 16 ulps), so t + h > t and the
 * point o + (t + h) d has moved. */
VS_FUNC float vs_walk_min_step(float t, float scale)
{
  return 2e-6f * max(abs(t), scale);
}

/* The distance from p along direction d (invD = 1 / d per axis) to where the ray leaves the
 * axis-aligned box [lo, hi] holding p: the nearest of the faces ahead on each axis, 1e30 on the axes
 * the ray runs parallel to (|d| <= 1e-20). Negative only if p lies beyond a face ahead (rounding). */
VS_FUNC float vs_box_exit_distance(vec3 p, vec3 d, vec3 invD, vec3 lo, vec3 hi)
{
  vec3 e3 = (mix(lo, hi, greaterThan(d, vec3(0.0f))) - p) * invD;
  e3 = mix(vec3(1e30f), e3, greaterThan(abs(d), vec3(1e-20f)));
  return min(e3.x, min(e3.y, e3.z));
}

/* The brick the ray o + t d is in just after t, at t + h / 2 (h = vs_walk_min_step): what a walk
 * reads there, and where the render kernel picks the voxel cell too. invBrickSize = 1 / brickSize. */
VS_FUNC ivec3 vs_brick_after(vec3 o, vec3 d, float t, float h, float invBrickSize)
{
  return ivec3(floor((o + (t + 0.5f * h) * d) * invBrickSize));
}

/* The ray distance where o + t d leaves the cube of bricks [b - r, b + r] (r >= 0 bricks; r = 0:
 * brick b alone), at least h past t. An empty brick at Chebyshev distance k from the nearest
 * non-empty one lies in a cube of radius k - 1 of empty bricks: one step crosses it. */
VS_FUNC float vs_brick_cube_exit(vec3 o, vec3 d, vec3 invD, float t, float h, ivec3 b, float r, float brickSize)
{
  vec3 p = o + t * d;
  vec3 lo = (vec3(b) - r) * brickSize;
  vec3 hi = (vec3(b) + r + 1.0f) * brickSize;
  return t + max(vs_box_exit_distance(p, d, invD, lo, hi), h);
}

VS_NAMESPACE_END

#endif
