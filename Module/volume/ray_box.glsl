/*
 * ray_box.glsl — the ray-box intersection every pass clips its rays with (GLSL only; included by
 * volume_access.glsl and by the pooled sweeps, which bind no volume image).
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

#endif
