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

VS_NAMESPACE_END

#endif
