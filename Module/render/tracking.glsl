/*
 * tracking.glsl — free-flight and transmittance estimation against the majorant segments
 * (majorant_walk.glsl): delta tracking of the camera ray to a real collision (delta_track, with
 * decomposition tracking of the brick's control extinction) and ratio tracking of a shadow ray's
 * transmittance (ratio_track, residual ratio tracking with the control; its first steps from the
 * pixel's Sobol strata). Included once, by mc_render.glsl.
 */

/* Delta tracking on [t0, t1): true at a real collision (tHit, its albedo). Distances inside a
 * segment count from its start, so steps far below the resolution of t still add up. The loops
 * only find the collision; its albedo is looked up once after them (lavapipe would run a lookup
 * inside the loop at every step, masked). */
bool delta_track(vec3 o, vec3 d, float t0, float t1, inout VsRng rng, uint cap, inout uint cost, out float tHit,
  out vec3 albedo)
{
  set_ray(o, d);
  float t = t0;
  uint steps = 0u;
  bool hit = false;
  float sHit = 0.0;
  bool controlHit = false;
  while (t < t1 && !hit)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    steps++;
    float h = tNext - t;
    /* Decomposition tracking (Kutz et al. 2017): the extinction is the brick's control c plus a
     * residual of majorant mu - c; the collision is the first of the control's (exponential, no
     * lookup) and the residual's (delta tracking at rate mu - c). c = 0: plain delta tracking. */
    float c = VS_SPEC_CAMERA_CONTROL ? gControl : 0.0;
    float hEnd = h;
    if (c > 0.0)
    {
      float tc = sample_exponential(vs_rng_float(rng), c);
      if (tc < h)
      {
        hEnd = tc;
        controlHit = true;
      }
    }
    float mr = mu - c;
    if (mr > 0.0)
    {
      float dt = 0.0;
      while (true)
      {
        /* One hash gives the step and the collision's test (the test's number is unused when the
         * step leaves the segment). */
        vec2 u = vs_rng_vec2(rng);
        dt += sample_exponential(u.x, mr);
        if (dt >= hEnd)
          break;
        VS_COUNT(0);
        vec3 x = o + (t + dt) * d;
        float s = kernel_sample(x);
        if (u.y * mr < vs_classify_extinction(s, gTF) * kernel_factor(x) - c || ++steps >= cap)
        {
          tHit = t + dt;
          sHit = s;
          hit = true;
          controlHit = false;
          break;
        }
      }
    }
    if (controlHit)
    {
      tHit = t + hEnd;
      hit = true;
    }
    t = tNext;
  }
  if (controlHit)
  {
    VS_COUNT(0);
    sHit = kernel_sample(o + tHit * d); /* the control's collision needs its albedo */
  }
  cost += steps;
  albedo = hit ? vs_classify(sHit, gTF).rgb : vec3(0.0);
  return hit;
}

/* Ratio tracking of the transmittance on [t0, t1), with Russian roulette once it is small. The
 * steps to the first two tentative collisions take their numbers from `strata` where it is not
 * negative (the pixel's Sobol sequence for its shadow rays), every other number from rng. */
float ratio_track(vec3 o, vec3 d, float t0, float t1, vec2 strata, inout VsRng rng, uint cap, inout uint cost)
{
  set_ray(o, d);
  float T = 1.0;
  float t = t0;
  uint steps = 0u;
  while (t < t1)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    steps++;
    float h = tNext - t;
    /* Residual ratio tracking (Novak et al. 2014): the brick's control extinction c is integrated
     * exactly, the residual sigma - c (majorant mu - c) by ratio tracking. c = 0: ratio tracking. */
    float c = VS_SPEC_SHADOW_CONTROL ? gControl : 0.0;
    if (c > 0.0)
    {
      T *= exp(-c * h);
      if (T < 0.05)
      {
        if (vs_rng_float(rng) < 0.5 || T == 0.0)
        {
          cost += steps;
          return 0.0;
        }
        T *= 2.0;
      }
    }
    float mr = mu - c;
    if (mr > 0.0)
    {
      float dt = 0.0;
      while (true)
      {
        vec2 u = vs_rng_vec2(rng); /* the step, and Russian roulette's number */
        if (strata.x >= 0.0)
        {
          u.x = strata.x;
          strata = vec2(strata.y, -1.0);
        }
        dt += sample_exponential(u.x, mr);
        if (dt >= h)
          break;
        VS_COUNT(0);
        vec3 x = o + (t + dt) * d;
        float sigma = vs_classify_extinction(kernel_sample(x), gTF) * kernel_factor(x);
        T *= max(0.0, 1.0 - (sigma - c) / mr);
        if (++steps >= cap)
        {
          cost += steps;
          return 0.0;
        }
        if (T < 0.05)
        {
          if (u.y < 0.5)
          {
            cost += steps;
            return 0.0;
          }
          T *= 2.0;
        }
      }
    }
    t = tNext;
  }
  cost += steps;
  return T;
}
