/*
 * rng.h — counter-based random numbers (docs/reference.md: "a PCG-style hash of pixel,
 * frame and dimension"). No state is carried between frames: the n-th number of
 * pixel p at frame f is pcg4d(p, f ^ seed, n), so a render with a fixed seed is
 * reproducible bit for bit, in any order of evaluation.
 *
 * pcg4d: Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020.
 */
#ifndef VS_RNG_H
#define VS_RNG_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

VS_FUNC uvec4 vs_pcg4d(uvec4 v)
{
  v = v * 1664525u + uvec4(1013904223u);
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v = v ^ (v >> uvec4(16u));
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

struct VsRng
{
  uvec3 key; /* (pixel x, pixel y, frame ^ seed scrambled) */
  uint counter;
};

VS_FUNC VsRng vs_rng_init(uvec2 pixel, uint frame, uint seed)
{
  VsRng r;
  r.key = uvec3(pixel.x, pixel.y, frame ^ (seed * 0x9E3779B9u));
  r.counter = 0u;
  return r;
}

/* A uint for dimension `counter`, then advance. */
VS_FUNC uint vs_rng_uint(VS_INOUT(VsRng) r)
{
  uvec4 h = vs_pcg4d(uvec4(r.key, r.counter));
  r.counter += 1u;
  return h.x;
}

/* A uniform uint as a float on [0,1): its top 24 bits, so every value is exact. */
VS_FUNC float vs_unit_float(uint h)
{
  return float(h >> 8u) * (1.0f / 16777216.0f);
}

VS_FUNC float vs_rng_float(VS_INOUT(VsRng) r)
{
  return vs_unit_float(vs_rng_uint(r));
}

VS_FUNC vec2 vs_rng_vec2(VS_INOUT(VsRng) r)
{
  uvec4 h = vs_pcg4d(uvec4(r.key, r.counter));
  r.counter += 1u;
  return vec2(vs_unit_float(h.x), vs_unit_float(h.y));
}

VS_NAMESPACE_END

#endif
