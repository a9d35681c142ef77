/*
 * sweep_access.glsl — extinction along rays for the sweeps and the brute force
 * (GLSL only). The including shader declares uVolume, uTF, uMajorant and a
 * buffer holding `VsSweepGlobals G` before including this file.
 */
#include "volume_access.glsl"

/* Extinction at index-space point p: post-classified, zero where a clip plane removes it. */
float vs_extinction(vec3 p)
{
  for (uint i = 0u; i < G.bricks.w; ++i)
  {
    if (dot(G.clipPlanes[i].xyz, p) + G.clipPlanes[i].w < 0.0)
      return 0.0;
  }
  return vs_classify(vs_sample_scalar(p, ivec3(G.dims.xyz)), G.tf).w;
}

/* The majorant of the brick holding p (0 = empty brick: no sample needed). */
float vs_brick_majorant(vec3 p)
{
  ivec3 b = clamp(ivec3(floor(p / G.march.y)), ivec3(0), ivec3(G.bricks.xyz) - 1);
  return imageLoad(uMajorant, b).r;
}

/* Optical depth along o + t d for t in [t0, t1] (world units), midpoint rule with
 * steps of at most G.march.x, skipping samples in empty bricks. */
float vs_optical_depth(vec3 o, vec3 d, float t0, float t1)
{
  if (!(t1 > t0))
    return 0.0;
  float len = t1 - t0;
  uint n = uint(ceil(len / G.march.x));
  n = max(n, 1u);
  float dt = len / float(n);
  float tau = 0.0;
  for (uint s = 0u; s < n; ++s)
  {
    vec3 p = o + (t0 + (float(s) + 0.5) * dt) * d;
    if (vs_brick_majorant(p) > 0.0)
      tau += vs_extinction(p) * dt;
  }
  return tau;
}
