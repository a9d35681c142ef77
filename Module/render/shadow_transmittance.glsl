/*
 * shadow_transmittance.glsl — a shadow ray's transmittance: ratio tracking (tracking.glsl), or, in
 * the mc_render_march_* modules (VS_RAY_MARCHING), Kettunen et al. 2021's unbiased ray marching.
 * Included once, by mc_render.glsl.
 */

#ifdef VS_RAY_MARCHING
/* Compiled only into the mc_render_march_* modules: the default kernel's SPIR-V stays the size it
 * was (lavapipe translates the whole module before specialization drops the unused branch; the
 * ray-marching code inside it cost every first frame ~0.3 s). */
/* The optical depth of [t0, t1) by a ray march with samples spaced `spacing` apart in residual
 * majorant optical depth (the majorant segments' mu - c, i.e. importance-sampled by the majorant
 * grid), one random offset for all (uniform jitter): sum of (sigma - c) / (mu - c) * spacing, plus the
 * control's c h exactly. Unbiased for the optical depth whatever the spacing. Sets `exhausted` when
 * the steps reach the cap (the caller scores 0, as ratio_track does). */
float march_optical_depth(vec3 o, vec3 d, float t0, float t1, float spacing, inout VsRng rng, uint cap,
  inout uint steps, inout bool exhausted)
{
  float tau = 0.0;
  float next = vs_rng_float(rng) * spacing; /* the next sample's residual depth past the segment's start */
  float t = t0;
  while (t < t1)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    float h = tNext - t;
    float c = VS_SPEC_SHADOW_CONTROL ? gControl : 0.0;
    tau += c * h;
    float mr = mu - c;
    float depth = mr * h;
    if (++steps >= cap)
    {
      exhausted = true;
      return tau;
    }
    if (mr > 0.0)
    {
      while (next < depth)
      {
        VS_COUNT(0);
        vec3 x = o + (t + next / mr) * d;
        float sigma = vs_classify_extinction(kernel_sample(x), gTF) * kernel_factor(x);
        tau += (sigma - c) / mr * spacing;
        next += spacing;
        if (++steps >= cap)
        {
          exhausted = true;
          return tau;
        }
      }
      next -= depth;
    }
    t = tNext;
  }
  return tau;
}

/* The residual majorant optical depth of [t0, t1) (sum of (mu - c) h over the majorant segments,
 * no volume reads) and the control's exact part (sum of c h). */
vec2 majorant_depth(vec3 o, vec3 d, float t0, float t1, uint cap, inout uint steps)
{
  vec2 depth = vec2(0.0);
  float t = t0;
  while (t < t1 && steps < cap)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    float c = VS_SPEC_SHADOW_CONTROL ? gControl : 0.0;
    depth += vec2(mu - c, c) * (tNext - t);
    steps++;
    t = tNext;
  }
  return depth;
}

/* Kettunen et al. 2021's unbiased ray-marching transmittance of [t0, t1) (ray_marching.h): the
 * control X0 from a jittered march, then the power series' terms prod (X0 - Xi) / (k! P(N >= k)) with
 * independent marches Xi, as many as the roulette takes. The estimate can be negative or above 1
 * (its mean is the transmittance). Marches spaced for Kettunen's sample count at the residual
 * majorant depth (an upper bound of the residual optical depth: more samples than for the mean). */
float march_transmittance(vec3 o, vec3 d, float t0, float t1, inout VsRng rng, uint cap, inout uint cost)
{
  set_ray(o, d);
  uint steps = 0u;
  vec2 depth = majorant_depth(o, d, t0, t1, cap, steps);
  if (steps >= cap)
  {
    cost += steps;
    return 0.0;
  }
  if (isinf(depth.x))
  {
    cost += steps; /* an infinite extinction on the ray (hostile input) */
    return 0.0;
  }
  if (!(depth.x > 0.0))
  {
    /* Nothing to march: every estimate is the control's exact depth, the series' terms are 0. */
    cost += steps;
    return exp(-depth.y);
  }
  float spacing = depth.x / vs_rm_sample_count(depth.x);
  bool exhausted = false;
  float x0 = march_optical_depth(o, d, t0, t1, spacing, rng, cap, steps, exhausted);
  float sum = 1.0, term = 1.0;
  for (uint k = 1u; !exhausted; ++k)
  {
    /* Term k with probability P(N >= k) / P(N >= k - 1): no fixed last order, so no truncation. */
    if (vs_rng_float(rng) >= vs_rm_continue_probability(k) || ++steps >= cap)
      break;
    float xk = march_optical_depth(o, d, t0, t1, spacing, rng, cap, steps, exhausted);
    term *= vs_rm_term_factor(x0, xk, k);
    sum += term;
  }
  cost += steps;
  if (exhausted || steps >= cap)
    return 0.0; /* the step budget ran out */
  float T = exp(-x0) * sum;
  /* exp(-X0) underflows to 0 while the product overflows only on a hostile extinction: 0 there. */
  return isnan(T) || isinf(T) ? 0.0 : T;
}
#endif

/* The shadow ray's transmittance: ratio tracking (residual with the control; `strata` as there), or
 * Kettunen's ray marching (VS_SPEC_TRANSMITTANCE). */
float shadow_transmittance(vec3 o, vec3 d, float t0, float t1, vec2 strata, inout VsRng rng, uint cap, inout uint cost)
{
#ifdef VS_RAY_MARCHING
  if (VS_SPEC_TRANSMITTANCE == VS_TRANSMITTANCE_RAY_MARCHING)
    return march_transmittance(o, d, t0, t1, rng, cap, cost);
#endif
  return ratio_track(o, d, t0, t1, strata, rng, cap, cost);
}
