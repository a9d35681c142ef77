/*
 * sweep_access.glsl — extinction along rays for the sweeps and the brute force
 * (GLSL only). The including shader declares a buffer holding `VsSweepParams G` and, without
 * VS_SWEEP_POOLED, uVolume, uTF, uMajorant and uFactor (with VS_FACTOR_IMAGE defined: the
 * extinction factor per voxel, the gradient opacity, read when the specialization constant
 * VS_SWEEP_FACTOR is 1), before including this file, and calls
 * vs_load_sweep_globals() first in main(): the per-sample code then reads the
 * globals from registers, not from the buffer (measured: lavapipe does not hoist them).
 *
 * With VS_SWEEP_POOLED defined, the includer declares instead two r32f images: uPool, the
 * pooled extinction (sigma_t already classified, P voxels per texel per axis), and
 * uPoolOccupancy, its occupancy (the max over each pooled brick's trilinear footprint).
 * Positions are then in pooled texel coordinates: vs_extinction is a trilinear read (8 imageLoads:
 * measured 1.5-2x cheaper on lavapipe than 8 storage-buffer loads), the march step is P times longer, and
 * clip planes are applied by the caller to the ray's interval (vs_clip_interval), not per sample.
 * The interpolation is the specialization constant VS_SWEEP_NEAREST (lavapipe runs both sides
 * of a branch, so the unused reconstruction is compiled out instead of branched around).
 */
#ifndef VS_SWEEP_POOLED
#include "volume_access.glsl"
#endif
#include "ray_box.glsl"
#include "brick_walk.h"

ivec3 gDims;
ivec3 gBricks;
float gBrickSize;
VsTransferFunction gTF;
uint gClipCount;
float gStep;
uint gInterpolation; /* interpolation.h (G.volume.interpolation) */

void vs_load_sweep_globals()
{
  gTF = G.volume.tf;
  gClipCount = G.volume.clipPlaneCount;
  gInterpolation = G.volume.interpolation;
#ifdef VS_SWEEP_POOLED
  gDims = ivec3(G.poolDims);
  gBricks = ivec3(G.poolBricks);
  gBrickSize = G.poolBrickSize;
  gStep = G.poolStep;
#else
  vs_set_cropping(G.volume.cropLo, G.volume.cropHi, G.volume.cropFlags); /* in index space: the pooled volume is masked when built */
  gDims = ivec3(G.volume.dims);
  gBricks = ivec3(G.volume.majorantBricks);
  gBrickSize = G.volume.majorantBrickSize;
  gStep = G.step;
#endif
}

/* The interval of t along index-space ray o + t d that the clip planes keep (empty when t.x >= t.y). */
vec2 vs_clip_interval(vec3 o, vec3 d)
{
  vec2 t = vec2(-1e30, 1e30);
  for (uint i = 0u; i < gClipCount; ++i)
    t = vs_clip_by_plane(G.volume.clipPlanes[i], o, d, t);
  return t;
}

#ifdef VS_SWEEP_POOLED
layout(constant_id = 0) const uint VS_SWEEP_NEAREST = 0u; /* 1: nearest-neighbour reconstruction */


/* Pooled extinction at pooled-texel point q (clamped to the volume): trilinear, or under nearest
 * interpolation the texel holding q, whose P^3 voxels' nearest-neighbour cells are exactly the
 * texel's block (so a mean-pooled texel is the block's mean extinction). */
float vs_extinction(vec3 q)
{
  vec3 c = clamp(q, vec3(0.0), vec3(gDims - 1));
  if (VS_SWEEP_NEAREST == 1u)
  {
    return imageLoad(uPool, min(ivec3(floor(c + 0.5)), gDims - 1)).r;
  }
  ivec3 i0 = ivec3(floor(c));
  ivec3 i1 = min(i0 + 1, gDims - 1);
  vec3 f = c - vec3(i0);
  float c00 = mix(imageLoad(uPool, i0).r, imageLoad(uPool, ivec3(i1.x, i0.y, i0.z)).r, f.x);
  float c10 = mix(imageLoad(uPool, ivec3(i0.x, i1.y, i0.z)).r, imageLoad(uPool, ivec3(i1.x, i1.y, i0.z)).r, f.x);
  float c01 = mix(imageLoad(uPool, ivec3(i0.x, i0.y, i1.z)).r, imageLoad(uPool, ivec3(i1.x, i0.y, i1.z)).r, f.x);
  float c11 = mix(imageLoad(uPool, ivec3(i0.x, i1.y, i1.z)).r, imageLoad(uPool, i1).r, f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* The occupancy of the pooled brick holding q (0 = empty brick: no sample needed). */
float vs_brick_majorant(vec3 q)
{
  ivec3 b = clamp(ivec3(floor(q / gBrickSize)), ivec3(0), gBricks - 1);
  return imageLoad(uPoolOccupancy, b).r;
}
#else
layout(constant_id = 1) const uint VS_SWEEP_FACTOR = 0u; /* 1: the extinction is scaled by uFactor */

/* Extinction at index-space point p: post-classified, times the extinction factor (the gradient
 * opacity) where there is one, zero where a clip plane removes it: what the renderer tracks. */
float vs_extinction(vec3 p)
{
  for (uint i = 0u; i < gClipCount; ++i)
  {
    if (dot(G.volume.clipPlanes[i].xyz, p) + G.volume.clipPlanes[i].w < 0.0)
      return 0.0;
  }
  float e = vs_classify_extinction(vs_sample(p, gDims, gInterpolation), gTF);
  if (VS_SWEEP_FACTOR == 1u)
    e *= vs_sample_factor(p, gDims, gInterpolation);
  return e;
}

/* The majorant of the brick holding p (0 = empty brick: no sample needed). */
float vs_brick_majorant(vec3 p)
{
  ivec3 b = clamp(ivec3(floor(p / gBrickSize)), ivec3(0), gBricks - 1);
  return imageLoad(uMajorant, b).r;
}
#endif

/* Distance from p along d to the exit of the brick holding p (>= 0; brick_walk.h). */
float vs_brick_exit(vec3 p, vec3 d)
{
  vec3 lo = floor(p / gBrickSize) * gBrickSize;
  return max(vs_box_exit_distance(p, d, 1.0 / d, lo, lo + gBrickSize), 0.0);
}

/* Optical depth along o + t d for t in [t0, t1] (world units), midpoint rule with
 * steps of at most the march step. Samples in empty bricks are skipped a whole brick
 * at a time (to the first sample past the brick's exit), so the sample positions and
 * the result are those of the plain midpoint rule. */
float vs_optical_depth(vec3 o, vec3 d, float t0, float t1)
{
  if (!(t1 > t0))
    return 0.0;
  float len = t1 - t0;
  uint n = max(uint(ceil(len / gStep)), 1u);
  float dt = len / float(n);
  float tau = 0.0;
  uint s = 0u;
  while (s < n)
  {
    vec3 p = o + (t0 + (float(s) + 0.5) * dt) * d;
    if (vs_brick_majorant(p) > 0.0)
    {
      tau += vs_extinction(p);
      s += 1u;
    }
    else
    {
      s += max(1u, uint(ceil(vs_brick_exit(p, d) / dt)));
    }
  }
  return tau * dt;
}
