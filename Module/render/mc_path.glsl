/*
 * mc_path.glsl — full transport: one path per sample, traced one segment per call (the camera ray or
 * a continuation), with its state kept between calls and dispatches (path_state.glsl). The radiative
 * transfer equation it estimates is in docs/reference.md ("What is rendered").
 *
 * At each real collision (delta tracking against the majorant bricks, tracking.glsl):
 *  - next-event estimation: gShadowRays directions from the strategy (Environment, TwoStep with the
 *    grid's cell at this point, ...: light_directions.glsl), each with a ratio-tracked shadow ray,
 *    scored  beta albedo f_HG(d, w) T(w) L_env(w) w_L / (n p_L(w));
 *  - the continuation: a direction from the Henyey-Greenstein phase (sampled exactly, so its weight is
 *    the albedo), which, if it escapes the volume, scores  beta L_env(w) w_P;
 *  - w_L and w_P by the power heuristic (mis.h); at the event limit there is no continuation and
 *    w_L = 1;
 *  - Russian roulette from gRouletteDepth events on (mis.h vs_roulette_survival).
 * With VS_SPEC_SURFACE (hybrid scattering, surface_scattering.glsl) the phase function is the event's
 * mixture of the phase and a surface BRDF on the gradient: next-event estimation evaluates the mixture's
 * kernel, the continuation samples it (weight k / p), and w_P weighs its density against the light pdf.
 * Continuations do not see VTK's opaque geometry (only the camera ray stops at its depth), as the
 * shadow rays of single scattering never did.
 * Included once, by mc_render.glsl, after the single-scattering estimator's helpers (camera_ray,
 * light_samples) which both estimators share.
 */

/* One segment of the path of pixel `pix`: when none is in flight, sample `sampleIndex`'s camera ray;
 * else the continuation. Returns true when the path has ended (its radiance and alpha in path.L).
 * Adds the back-edges of its tracking and shadow rays to trackCost and shadowCost, and says whether
 * it reached a scattering event. */
bool path_segment(uvec2 pix, uint sampleIndex, float depth, uint perRay, inout Path path, inout uint trackCost,
  inout uint shadowCost, out bool scattered)
{
  scattered = false;
  VsRng rng = vs_rng_init(pix, sampleIndex, gSeed);
  uvec3 sobolSeeds = VS_SPEC_SOBOL ? vs_pcg4d(uvec4(pix, gSeed, 0x50b01u)).xyz : uvec3(0u);
  bool camera = !path.inFlight;
  CameraRay r;
  if (camera)
  {
    r = camera_ray(pix, sampleIndex, depth, rng, sobolSeeds);
    path = path_idle();
    path.inFlight = true;
  }
  else
  {
    rng.counter = path.counter;
    r.o = path.x;
    r.dw = path.dw;
    r.d = (gWorldToIndex * vec4(path.dw, 0.0)).xyz;
    vec2 ti = ray_interval(r.o, r.d);
    r.t0 = max(ti.x, 0.0);
    r.t1 = ti.y;
    r.seesEnvironment = false;
  }

  bool scatter = false;
  float tHit = 0.0;
  vec3 albedo = vec3(0.0);
  if (camera && VS_SPEC_CAMERA == VS_CAMERA_RESERVOIR)
  {
    float T = 1.0;
    if (r.t0 < r.t1)
      camera_reservoir(r.o, r.d, r.t0, r.t1, rng, VS_TRACKING_CAP, trackCost, tHit, albedo, T);
    scatter = tHit >= 0.0 && r.t0 < r.t1 && any(greaterThan(albedo, vec3(0.0)));
    path.L = r.seesEnvironment ? vec4(T * env_radiance_display(r.dw), gEscapeAlpha > 0.5 ? 1.0 : 1.0 - T)
                               : vec4(0.0, 0.0, 0.0, 1.0 - T);
  }
  else if (r.t0 < r.t1 && delta_track(r.o, r.d, r.t0, r.t1, rng, VS_TRACKING_CAP, trackCost, tHit, albedo))
  {
    if (camera)
      path.L.a = 1.0;
    scatter = any(greaterThan(albedo, vec3(0.0)));
  }
  else if (camera)
  {
    if (r.seesEnvironment)
      path.L = vec4(env_radiance_display(r.dw), gEscapeAlpha);
  }
  else
  {
    /* A continuation escapes: the environment it sees, weighted against light sampling. */
    path.L.rgb += path.beta * (path.escapeWeight * env_radiance(r.dw));
  }

  bool ended = true;
  if (scatter)
  {
    scattered = true;
    vec3 x = r.o + tHit * r.d;
    uint events = path.events + 1u;
    bool continues = events < gMaxEvents;
    bool weighted = continues && (gMis == VS_MIS_POWER || gMis == VS_MIS_BALANCE);
    prepare_directions(x, gStrategy, rng);
    if (VS_SPEC_SURFACE != 0u)
      surface_event(x, albedo); /* hybrid scattering: the event's surface probability and normal */
    gShadowLeft = gShadowBudget;
    if (gMis != VS_MIS_PHASE_ONLY && events >= gLightLo && events <= gLightHi)
    {
      vec3 sum = light_samples(x, r.dw, sampleIndex, events == 1u, weighted, rng, sobolSeeds, perRay, shadowCost);
      /* With the surface lobe the sum holds the event's kernel, albedo included. */
      path.L.rgb += VS_SPEC_SURFACE != 0u ? path.beta * sum / float(gShadowRays)
                                          : path.beta * albedo * sum / float(gShadowRays);
    }
    /* issue 38: VTK's lights (delta lights: only next-event estimation finds them, in every MIS mode). */
    if (VS_SPEC_LIGHTS != 0u && events >= gLightLo && events <= gLightHi)
      path.L.rgb += path.beta * scene_light_samples(x, r.dw, albedo, rng, perRay, shadowCost);
    if (continues)
    {
      float phasePdf;
      vec3 w;
      vec3 weight = albedo; /* f_HG / p_HG = 1 */
      if (VS_SPEC_SURFACE != 0u)
      {
        /* The mixture's direction; its weight k / p (p the mixture's density, against the light pdf below). */
        vec3 k;
        w = event_sample(r.dw, rng, k, phasePdf);
        weight = phasePdf > 0.0 ? k / phasePdf : vec3(0.0);
      }
      else
        w = vs_sample_hg(r.dw, gAnisotropy, vs_rng_vec2(rng), phasePdf);
      float escapeWeight = 1.0;
      if (gMis == VS_MIS_LIGHT_ONLY)
        escapeWeight = 0.0;
      else if (weighted)
      {
        float lightPdf = direction_pdf(gStrategy, w);
        float n = float(gShadowRays);
        escapeWeight = gMis == VS_MIS_POWER ? vs_power_heuristic(1.0, phasePdf, n, lightPdf)
                                            : vs_balance_heuristic(1.0, phasePdf, n, lightPdf);
      }
      vec3 beta = path.beta * weight;
      float q = vs_roulette_survival(beta, events, gRouletteDepth);
      if (VS_SPEC_SURFACE != 0u && !any(greaterThan(beta, vec3(0.0))))
        q = 0.0; /* a surface direction below the surface: nothing to carry */
      if (q >= 1.0 || vs_rng_float(rng) < q)
      {
        path.beta = beta / q;
        path.x = x;
        path.dw = w;
        path.events = events;
        path.escapeWeight = escapeWeight;
        ended = false;
      }
    }
  }
  path.counter = rng.counter;
  if (ended)
  {
    path.inFlight = false;
    /* Non-finite contributions (should not happen) are dropped rather than poisoning the pixel. */
    if (any(isnan(path.L)) || any(isinf(path.L)))
      path.L = vec4(0.0);
  }
  return ended;
}
