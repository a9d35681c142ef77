/*
 * octahedral.h — the equal-area octahedral map between the unit sphere and
 * [0,1)^2 (Clarberg, "Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD",
 * JGT 13(3), 2008). Equal area: every texel of a 2^k x 2^k map covers the same
 * solid angle 4π/4^k, so a texel's probability turns into a solid-angle pdf by
 * the constant factor texels/(4π). +Z maps to the centre (0.5, 0.5), -Z to the
 * four corners.
 */
#ifndef VS_OCTAHEDRAL_H
#define VS_OCTAHEDRAL_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The solid angle of each texel of an n x n map: 4π/n². */
VS_FUNC float vs_octa_texel_solid_angle(uint n)
{
  return 4.0f * VS_PI / (float(n) * float(n));
}

/* [0,1]^2 -> unit direction. */
VS_FUNC vec3 vs_octa_to_dir(vec2 uv)
{
  float u = 2.0f * uv.x - 1.0f;
  float v = 2.0f * uv.y - 1.0f;
  float up = abs(u);
  float vp = abs(v);
  float signedDistance = 1.0f - (up + vp);
  float d = abs(signedDistance);
  float r = 1.0f - d;
  float phi = (r == 0.0f ? 1.0f : (vp - up) / r + 1.0f) * (VS_PI / 4.0f);
  float z = vs_copysign(1.0f - r * r, signedDistance);
  float cosPhi = vs_copysign(cos(phi), u);
  float sinPhi = vs_copysign(sin(phi), v);
  float s = r * sqrt(max(0.0f, 2.0f - r * r));
  return vec3(cosPhi * s, sinPhi * s, z);
}

/* unit direction -> [0,1]^2. */
VS_FUNC vec2 vs_dir_to_octa(vec3 d)
{
  float x = abs(d.x);
  float y = abs(d.y);
  float z = abs(d.z);
  float r = sqrt(max(0.0f, 1.0f - z));
  float a = max(x, y);
  float b = min(x, y);
  b = a == 0.0f ? 0.0f : b / a;
  float phi = atan(b) * (2.0f / VS_PI);
  if (x < y)
    phi = 1.0f - phi;
  float v = phi * r;
  float u = r - v;
  if (d.z < 0.0f)
  {
    float t = u;
    u = 1.0f - v;
    v = 1.0f - t;
  }
  u = vs_copysign(u, d.x);
  v = vs_copysign(v, d.y);
  return vec2(0.5f * (u + 1.0f), 0.5f * (v + 1.0f));
}

/* The texel (of an n x n map) that holds direction d. */
VS_FUNC uvec2 vs_dir_to_texel(vec3 d, uint n)
{
  vec2 uv = vs_dir_to_octa(d);
  return uvec2(min(uvec2(uv * float(n)), uvec2(n - 1u)));
}

/* The direction at the centre of texel t of an n x n map. */
VS_FUNC vec3 vs_texel_dir(uvec2 t, uint n)
{
  return vs_octa_to_dir((vec2(t) + vec2(0.5f)) / float(n));
}

/* Texel t of an n x n map, with texels one step beyond an edge folded back across it as the
 * sphere does: the edge u = 0 meets itself mirrored, (0, v) and (0, 1 - v) are one direction
 * (likewise u = 1, v = 0, v = 1), so texel (-1, y) is texel (0, n - 1 - y). */
VS_FUNC uvec2 vs_octa_wrap(ivec2 t, int n)
{
  if (t.x < 0)
    t = ivec2(0, n - 1 - t.y);
  else if (t.x >= n)
    t = ivec2(n - 1, n - 1 - t.y);
  if (t.y < 0)
    t = ivec2(n - 1 - t.x, 0);
  else if (t.y >= n)
    t = ivec2(n - 1 - t.x, n - 1);
  return uvec2(clamp(t, ivec2(0), ivec2(n - 1)));
}

/* Bilinear interpolation between texel centres of an n x n map at uv: corner c (0..3) of the
 * four texels around uv, folded across the edges (vs_octa_wrap), and its weight; the four
 * weights sum to 1. For display (the visible background), not for lighting: the lighting's
 * environment is piecewise constant per texel, the function the sampling integrates. */
VS_FUNC uvec2 vs_octa_bilinear_texel(vec2 uv, uint n, uint c, VS_OUT(float) weight)
{
  vec2 p = uv * float(n) - vec2(0.5f);
  vec2 f = floor(p);
  vec2 w = p - f;
  ivec2 off = ivec2(int(c & 1u), int(c >> 1u));
  weight = (off.x == 1 ? w.x : 1.0f - w.x) * (off.y == 1 ? w.y : 1.0f - w.y);
  return vs_octa_wrap(ivec2(f) + off, int(n));
}

VS_NAMESPACE_END

#endif
