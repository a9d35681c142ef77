/*
 * camera_reservoir.glsl — the camera estimator VS_CAMERA_RESERVOIR: the camera ray ratio-tracked,
 * one scatter point resampled from all its tentative collisions. Included once, by mc_render.glsl.
 */

/* The camera ray by ratio tracking with one scatter point resampled from all its tentative
 * collisions (VS_CAMERA_RESERVOIR). At the tentative collisions x_i (rate mu) of the ray, ratio
 * tracking's running transmittance T_i makes sum_i T_i sigma_s(x_i) / mu L_s(x_i) an unbiased
 * estimate of the single-scattered light (the collision estimator); one point j drawn with
 * probability s_j / S (s_i: the luminance of T_i sigma_s(x_i) / mu, S their sum: a weighted
 * reservoir over the walk, no second loop) and scored (T_j sigma_s(x_j) / mu) S / s_j L_s(x_j) has
 * the same expectation, for one shadow ray. `weight` is that factor (rgb: T_j albedo_j sigma_t / mu
 * S / s_j), `T` the ray's transmittance (its alpha is 1 - T), tSel < 0 when nothing scatters. */
void camera_reservoir(vec3 o, vec3 d, float t0, float t1, inout VsRng rng, uint cap, inout uint cost, out float tSel,
  out vec3 weight, out float T)
{
  set_ray(o, d);
  tSel = -1.0;
  weight = vec3(0.0);
  T = 1.0;
  float S = 0.0, sSel = 0.0;
  vec3 wSel = vec3(0.0);
  float t = t0;
  uint steps = 0u;
  bool alive = true;
  while (t < t1 && alive)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    steps++;
    if (mu > 0.0)
    {
      float h = tNext - t;
      float dt = 0.0;
      while (true)
      {
        vec2 u = vs_rng_vec2(rng); /* the step, and the reservoir's choice */
        dt += sample_exponential(u.x, mu);
        if (dt >= h)
          break;
        VS_COUNT(0);
        vec3 x = o + (t + dt) * d;
        vec4 c = vs_classify(kernel_sample(x), gTF);
        c.w *= kernel_factor(x);
        vec3 ws = T * c.rgb * (c.w / mu);
        float si = vs_luminance(ws);
        if (si > 0.0)
        {
          S += si;
          if (u.y * S < si)
          {
            tSel = t + dt;
            wSel = ws;
            sSel = si;
          }
        }
        T *= max(0.0, 1.0 - c.w / mu);
        if (++steps >= cap)
          T = 0.0;
        else if (T < 0.05)
        {
          if (vs_rng_float(rng) < 0.5)
            T = 0.0;
          else
            T *= 2.0;
        }
        if (T == 0.0)
        {
          alive = false;
          break;
        }
      }
    }
    t = tNext;
  }
  cost += steps;
  if (tSel >= 0.0)
    weight = wSel * (S / sSel);
}
