/*
 * ray_box.glsl — the ray-box intersection and the clip-plane step every pass clips its rays with
 * (GLSL only; included by volume_access.glsl and by the pooled sweeps, which bind no volume image).
 */
#ifndef VS_RAY_BOX_GLSL
#define VS_RAY_BOX_GLSL

/* Ray-box intersection in index space; returns (tNear, tFar), empty when tNear >= tFar. */
vec2 vs_intersect_box(vec3 o, vec3 d, vec3 bmin, vec3 bmax)
{
  vec3 inv = 1.0 / d;
  vec3 ta = (bmin - o) * inv;
  vec3 tb = (bmax - o) * inv;
  vec3 tmin = min(ta, tb);
  vec3 tmax = max(ta, tb);
  /* An axis-parallel ray (d = 0 on an axis) gives inf/-inf or NaN when it lies on a face;
   * treat NaN as "no constraint" so rays on a face are inside. */
  float t0 = max(max(isnan(tmin.x) ? -1e30 : tmin.x, isnan(tmin.y) ? -1e30 : tmin.y),
    isnan(tmin.z) ? -1e30 : tmin.z);
  float t1 = min(min(isnan(tmax.x) ? 1e30 : tmax.x, isnan(tmax.y) ? 1e30 : tmax.y),
    isnan(tmax.z) ? 1e30 : tmax.z);
  return vec2(t0, t1);
}

/* The interval t of the ray o + t d after the clip plane (xyz normal, w offset) keeps the side
 * where dot(n, x) + w >= 0. A ray parallel to the plane (|dot(n, d)| < 1e-20) keeps t on the kept
 * side and loses it all on the other (1, 0: empty; later planes cannot make it non-empty again).
 * The passes loop over their planes themselves, reading each in place: an array of planes passed as
 * an argument is copied into every lane's registers on lavapipe (~2,000 instructions per call). */
vec2 vs_clip_by_plane(vec4 plane, vec3 o, vec3 d, vec2 t)
{
  float dn = dot(plane.xyz, d);
  float on = dot(plane.xyz, o) + plane.w;
  if (abs(dn) < 1e-20)
    return on < 0.0 ? vec2(1.0, 0.0) : t;
  float th = -on / dn;
  return dn > 0.0 ? vec2(max(t.x, th), t.y) : vec2(t.x, min(t.y, th));
}

#endif
