/*
 * mc_render.glsl — unbiased progressive Monte Carlo single scattering under
 * environment light (von Radziewsky et al. 2017, Sec. 4 and 7). Included by mc_render_<format>.comp,
 * which defines VS_VIS_FORMAT (the visibility grid's storage format), and by mc_render_env.comp,
 * which also defines VS_NO_GRID (Environment and Uniform only: no grid code compiled in).
 *
 * Per sample: a jittered camera ray; free-flight distance by delta tracking against
 * the majorant bricks (empty bricks skipped); at a real collision, one direction from
 * the strategy (Uniform, Environment, Visibility, Combined or TwoStep), its
 * transmittance to the box by ratio tracking, and
 *     L = albedo * (1/4pi) * T * L_env(w) / pdf(w).
 * The approximate visibility only shapes the pdf; T is the true transmittance, which
 * keeps the estimator unbiased. Escaping rays see the environment (opaque, or with the alpha of
 * the volume's coverage: P.background = VS_BACKGROUND_ENVIRONMENT_COVERAGE) or are transparent, so VTK's background shows; rays
 * reaching the opaque depth are transparent.
 * Accumulates compensated (Kahan) sums of (rgb, alpha) and their squares per pixel, and how many
 * samples they hold; one dispatch brings every pixel towards `target` samples.
 *
 * Delta and ratio tracking are one loop each, of one step per iteration (the next majorant
 * segment, or a tentative collision): a SIMD group then runs each loop as long as its longest lane.
 *
 * Lavapipe ends every loop once an invocation's loops have taken 65535 back-edges together
 * (llvmpipe's loop limiter), silently: that, not the loop itself, gave wrong pixels past ~130
 * TwoStep samples per dispatch. The sample loop keeps `cost`, an upper bound of the group's
 * back-edges (the same in every lane), and starts a sample only while one more at its most
 * expensive fits below VS_LOOP_BUDGET; the pixels it leaves short of the target are counted, and
 * the host dispatches again until none is. A pixel's samples are its indices 0, 1, ... in order
 * whatever the split, so its sums are the same bits for any split into dispatches and frames.
 *
 * The kernel's parts, in the order this file includes them: mc_resources.glsl (bindings,
 * specialization constants, registers), kernel_volume.glsl (the volume's scalar and the ray's
 * interval), majorant_walk.glsl (the majorant segments), light_directions.glsl (the
 * strategy's direction and pdf), tracking.glsl (delta and ratio tracking),
 * shadow_transmittance.glsl (ratio tracking or ray marching), camera_reservoir.glsl (the reservoir
 * camera estimator); then here the loop budget, one sample and main().
 */
#include "brick_walk.h"
#include "octahedral.h"
#ifdef VS_RAY_MARCHING
#include "ray_marching.h"
#endif
#include "mc_params.h"
#include "mis.h"
#include "sphere.h"
#include "rng.h"
#include "sobol.h"
#include "strategies.h"
#include "scene_lights.h"
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "mc_resources.glsl"

#include "kernel_volume.glsl"

#include "majorant_walk.glsl"

#include "light_directions.glsl"

#include "tracking.glsl"

#include "shadow_transmittance.glsl"

#include "camera_reservoir.glsl"

#include "surface_scattering.glsl"

/* ------------------------------------------------------------------ the loop budget */

/* Back-edges a scatter step may take, an upper bound: the environment's descent (K levels), the
 * shadow ray's clip planes; for the grid strategies the table's descent (log2 D levels), or
 * direction_values' loops over the D x D map (one pass for one cell; clear, 8 corners and weight
 * for trilinear cells), its sum pyramid (D^2 / 3 values in log2 D loops) and the warp's descent. */
uint scatter_cost(uint strategy, uint D, uint K, uint cellMode)
{
  uint DD = D * D;
  uint cost = 16u + 2u * K + 6u + 4u;
  if (strategy == VS_STRATEGY_UNIFORM || strategy == VS_STRATEGY_ENVIRONMENT || D == 0u)
    return cost;
  if (VS_SPEC_DEFENSIVE != 0u)
    cost += 16u + 4u * D; /* both branches' descents and probabilities (lavapipe runs both) */
  if (VS_SPEC_TABLE != 0u)
    return cost + 16u + 2u * D;
  cost += 16u + 2u * D + (cellMode == VS_CELL_STOCHASTIC ? DD : 2u * DD + 8u * (DD + 1u)) + DD / 2u + 8u;
  return cost;
}

/* The camera ray's start (its clip planes, the background's 4 texels). */
const uint VS_START_COST = 16u;
/* Loops a sample enters with no lane that needs them (lavapipe runs a loop body once even then). */
const uint VS_SAMPLE_SLACK = 16u;

/* The steps (loop iterations) one tracker may take before it gives up (delta_track,
 * ratio_track): what a sample may cost at most stays well inside a dispatch's budget. */
const uint VS_TRACKING_CAP = 8192u;

/* ------------------------------------------------------------------ one sample */

/* The compensated per-pixel accumulators, held in registers across the samples of a dispatch
 * (loaded once, stored once). Kahan summation: the sum stays exact to float precision over 1e5+
 * samples. The same additions in the same order for any split of the samples into dispatches. */
struct Accumulator
{
  vec4 sum, comp, sq;
};

void accumulate(inout Accumulator acc, vec4 v)
{
  vec4 y = v - acc.comp;
  vec4 t = acc.sum + y;
  acc.comp = (t - acc.sum) - y;
  acc.sum = t;
  /* Squares of the radiance scaled to the environment's brightest texel: radiance below ~1e-19
   * (a dim map in physical units) would square to 0 in float and report no variance. */
  float scale = gSquareScale > 0.0 ? gSquareScale : 1.0;
  vec4 w = v * vec4(scale, scale, scale, 1.0);
  acc.sq += w * w;
}

/* The camera ray of sample `sampleIndex` of pixel `pix`: world direction dw, index-space origin o and
 * direction d, its interval [t0, t1) in the box (up to the opaque depth), and whether it sees the
 * environment if it escapes. Under the Sobol sampler (VS_SAMPLER_SOBOL) the pixel jitter comes from the
 * pixel's own scrambled Sobol sequence sobolSeeds.x, indexed by the sample; else from rng. */
struct CameraRay
{
  vec3 o, d, dw;
  float t0, t1;
  bool seesEnvironment;
};

CameraRay camera_ray(uvec2 pix, uint sampleIndex, float depth, inout VsRng rng, uvec3 sobolSeeds)
{
  uint W = gWidth, H = gHeight;
  vec2 jitter = VS_SPEC_SOBOL ? vs_sobol_2d(sampleIndex, sobolSeeds.x) : vs_rng_vec2(rng);
  vec2 ndc = (vec2(pix) + jitter) / vec2(W, H) * 2.0 - 1.0;
  vec4 pn = gInvViewProj * vec4(ndc, -1.0, 1.0);
  vec4 pf = gInvViewProj * vec4(ndc, 1.0, 1.0);
  vec3 ow = pn.xyz / pn.w;
  CameraRay r;
  r.dw = normalize(pf.xyz / pf.w - ow);
  float tDepth = 1e30;
  if (depth < 1.0)
  {
    vec4 pd = gInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    tDepth = dot(pd.xyz / pd.w - ow, r.dw);
  }
  r.o = (gWorldToIndex * vec4(ow, 1.0)).xyz;
  r.d = (gWorldToIndex * vec4(r.dw, 0.0)).xyz;
  vec2 ti = ray_interval(r.o, r.d);
  r.t0 = max(ti.x, 0.0);
  r.t1 = min(ti.y, tDepth);
  r.seesEnvironment = tDepth >= 1e30 && gBackgroundVisible;
  return r;
}

/* Next-event estimation at scatter point x (index space; prepare_directions done there) of a ray
 * travelling along world direction dw: gShadowRays directions from the strategy, each with its
 * transmittance to the box. Returns the sum over them of T L_env / pdf (single scattering: the caller
 * multiplies by the isotropic phase), or, under full transport (VS_SPEC_PATH), of
 * T L_env f_HG w_L / pdf (with VS_SPEC_SURFACE, T L_env k w_L / pdf, k the event's mixture kernel with its
 * albedo, surface_scattering.glsl), w_L the MIS weight against the phase-sampled continuation where `weighted`
 * (mis.h), else 1. Their mean over the rays is an unbiased estimate of the light in-scattered at x.
 * Under the Sobol sampler the first event's directions and the first two steps of each shadow ray's
 * tracking come from the pixel's Sobol sequences sobolSeeds.y and .z, indexed by the sample (a pixel's
 * samples stratified); deeper events draw from rng. */
vec3 light_samples(vec3 x, vec3 dw, uint sampleIndex, bool firstEvent, bool weighted, inout VsRng rng,
  uvec3 sobolSeeds, uint scatterCostPerRay, inout uint shadowCost)
{
  vec3 sum = vec3(0.0);
  bool sobol = VS_SPEC_SOBOL && firstEvent;
  uint shadowLeft = gShadowBudget; /* the same in every lane here: it drops by the group's steps */
  for (uint k = 0u; k < gShadowRays; ++k)
  {
    float pdf;
    /* The light's 2D number: the pixel's Sobol point (its samples' directions stratified), or the
     * sample's own random pair. */
    vec2 u = sobol ? vs_sobol_2d(sampleIndex * gShadowRays + k, sobolSeeds.y) : vs_rng_vec2(rng);
    vec3 w = sample_direction(gStrategy, u, pdf);
    vec3 Le = pdf > 0.0 ? env_radiance(w) : vec3(0.0);
    uint steps = 0u;
    if (any(greaterThan(Le, vec3(0.0))))
    {
      vec3 di = (gWorldToIndex * vec4(w, 0.0)).xyz;
      vec2 ts = ray_interval(x, di);
      /* The first two steps of its ratio tracking from the pixel's third Sobol sequence, indexed as
       * the direction's: a pixel's shadow rays meet the medium at stratified depths (on the skin
       * most of the transmittance's variance): 8-15% lower MSE at equal spp (docs/benchmarks.md). */
      vec2 strata = sobol ? vs_sobol_2d(sampleIndex * gShadowRays + k, sobolSeeds.z) : vec2(-1.0);
      float T = shadow_transmittance(x, di, 0.0, ts.y, strata, rng, min(VS_TRACKING_CAP, max(shadowLeft, 1u)), steps);
#ifdef VS_COUNT_LOOKUPS
      gShadowRaysCast++;
      gShadowRaysBlocked += T < 0.01 ? 1u : 0u;
#endif
      if (VS_SPEC_PATH == 0u)
        sum += T * Le / pdf;
      else if (VS_SPEC_SURFACE != 0u)
      {
        /* Hybrid scattering: the event's mixture kernel (albedo included) against its sampling density. */
        float scatterPdf;
        vec3 k = event_kernel(dw, w, scatterPdf);
        float weight = 1.0;
        if (weighted)
          weight = gMis == VS_MIS_POWER ? vs_power_heuristic(float(gShadowRays), pdf, 1.0, scatterPdf)
                                        : vs_balance_heuristic(float(gShadowRays), pdf, 1.0, scatterPdf);
        sum += T * Le * k * (weight / pdf);
      }
      else
      {
        float phase = vs_hg_pdf(dot(dw, w), gAnisotropy);
        float weight = 1.0;
        if (weighted)
          weight = gMis == VS_MIS_POWER ? vs_power_heuristic(float(gShadowRays), pdf, 1.0, phase)
                                        : vs_balance_heuristic(float(gShadowRays), pdf, 1.0, phase);
        sum += T * Le * (phase * weight / pdf);
      }
    }
    /* The lanes here run each shadow ray's loop as long as the longest of them. */
    uint groupSteps = subgroupMax(steps);
    shadowLeft -= min(shadowLeft, groupSteps);
    shadowCost += groupSteps + scatterCostPerRay;
  }
  gShadowLeft = shadowLeft; /* issue 38: VTK's lights take what is left (scene_lights.glsl) */
  return sum;
}

#include "scene_lights.glsl"

/* Single scattering with the isotropic phase (VS_SPEC_PATH 0): one sample of pixel `pix`, sample
 * `sampleIndex` of the image (its random numbers depend on the pixel, the sample index and the seed
 * only). Returns (rgb, alpha); adds the back-edges of its camera and shadow rays to cameraCost and
 * shadowCost, and says whether it scattered. */
vec4 render_sample(uvec2 pix, uint sampleIndex, float depth, uint scatterCostPerRay, inout uint cameraCost,
  inout uint shadowCost, out bool scattered)
{
  scattered = false;
  VsRng rng = vs_rng_init(pix, sampleIndex, gSeed);
  /* Under the Sobol sampler (VS_SAMPLER_SOBOL) the pixel jitter, the light directions and the first
   * two steps of each shadow ray's tracking come from the pixel's own scrambled Sobol sequences
   * (sobol.h; three seeds, so the three are independent), indexed by the sample: unbiased, and
   * stratified across the pixel's samples; everything else from the sample's hash stream. */
  uvec3 sobolSeeds = VS_SPEC_SOBOL ? vs_pcg4d(uvec4(pix, gSeed, 0x50b01u)).xyz : uvec3(0u);
  CameraRay r = camera_ray(pix, sampleIndex, depth, rng, sobolSeeds);

  vec4 result = vec4(0.0);
  /* The scatter point, and the factor its in-scattered light is scored with (albedo for delta
   * tracking's collision; the reservoir's weight otherwise). */
  bool scatter = false;
  float tHit = 0.0;
  vec3 albedo = vec3(0.0);
  if (VS_SPEC_CAMERA == VS_CAMERA_RESERVOIR)
  {
    float T = 1.0;
    if (r.t0 < r.t1)
      camera_reservoir(r.o, r.d, r.t0, r.t1, rng, VS_TRACKING_CAP, cameraCost, tHit, albedo, T);
    scatter = tHit >= 0.0 && r.t0 < r.t1 && any(greaterThan(albedo, vec3(0.0)));
    result = r.seesEnvironment ? vec4(T * env_radiance_display(r.dw), gEscapeAlpha > 0.5 ? 1.0 : 1.0 - T)
                               : vec4(0.0, 0.0, 0.0, 1.0 - T);
  }
  else if (r.t0 < r.t1 && delta_track(r.o, r.d, r.t0, r.t1, rng, VS_TRACKING_CAP, cameraCost, tHit, albedo))
  {
    result.a = 1.0;
    scatter = any(greaterThan(albedo, vec3(0.0)));
  }
  else if (r.seesEnvironment)
  {
    result = vec4(env_radiance_display(r.dw), gEscapeAlpha);
  }
  if (scatter)
  {
    scattered = true;
    vec3 x = r.o + tHit * r.d;
    prepare_directions(x, gStrategy, rng);
    /* gShadowRays directions per scatter point (splitting): their mean is an unbiased estimate
     * of the in-scattered light at x, for the cost of one camera ray. */
    vec3 sum = light_samples(x, r.dw, sampleIndex, true, false, rng, sobolSeeds, scatterCostPerRay, shadowCost);
    result.rgb += albedo * VS_INV_4PI * sum / float(gShadowRays);
  }
  /* Non-finite contributions (should not happen) are dropped rather than poisoning the pixel. */
  if (any(isnan(result)) || any(isinf(result)))
    result = vec4(0.0);
  return result;
}

#include "path_state.glsl"

#include "mc_path.glsl"

void main()
{
  uvec2 pix = gl_GlobalInvocationID.xy;
  uint W = P.camera.width, H = P.camera.height;
  bool inside = pix.x < W && pix.y < H;
  gEnvScale = P.environmentIntensity;
  gEpsilon = P.visibilityEpsilon;
  gSquareScale = P.squareScale;
  gMixture = P.defensiveWeight;
  gEnvLevels = P.environmentLevels;
  gBoxMin = P.volume.boxMin;
  gBoxMax = P.volume.boxMax;
  gCellSize = P.grid.cellSize;
  gGridCells = P.grid.cells;
  gGridSide = P.grid.side;
  gWidth = W;
  gHeight = H;
  gSeed = P.camera.seed;
  gBackgroundVisible = P.background != VS_BACKGROUND_TRANSPARENT;
  gEscapeAlpha = P.background == VS_BACKGROUND_ENVIRONMENT_COVERAGE ? 0.0 : 1.0;
  gWorldToIndex = P.volume.worldToIndex;
  gInvViewProj = P.camera.invViewProj;
  /* Unrolled (the kernel's loops count against lavapipe's loop limiter, see the top): as many as
   * VS_MAX_CLIP_PLANES (gClipPlanes' size would not compile otherwise). */
  gClipPlanes[0] = P.volume.clipPlanes[0];
  gClipPlanes[1] = P.volume.clipPlanes[1];
  gClipPlanes[2] = P.volume.clipPlanes[2];
  gClipPlanes[3] = P.volume.clipPlanes[3];
  gClipPlanes[4] = P.volume.clipPlanes[4];
  gClipPlanes[5] = P.volume.clipPlanes[5];
  gClipPlanes[6] = P.volume.clipPlanes[6];
  gClipPlanes[7] = P.volume.clipPlanes[7];
  gDims = ivec3(P.volume.dims);
  gQuadOffset = P.volume.quadZero;
  gBricks = ivec3(P.volume.majorantBricks);
  gBrickSize = P.volume.majorantBrickSize;
  gInvBrickSize = 1.0 / P.volume.majorantBrickSize;
  gTF = P.volume.tf;
  gEnvSize = 1u << P.environmentLevels;
  gClipCount = P.volume.clipPlaneCount;
  gStrategy = VS_SPEC_STRATEGY;
  gShadowRays = clamp(P.shadowRays, 1u, 64u);
  gMaxEvents = clamp(P.maxEvents, 1u, VS_MAX_SCATTERING_EVENTS);
  gAnisotropy = P.anisotropy;
  gRouletteDepth = P.rouletteDepth > 0u ? P.rouletteDepth : VS_DEFAULT_ROULETTE_DEPTH;
  gMis = P.mis;
  gLightLo = P.lightEvents == 0u ? 1u : (P.lightEvents & 0xffffu);
  gLightHi = P.lightEvents == 0u ? 0xffffffffu : (P.lightEvents >> 16u);
  gRefineDepth = P.cellWalkDepth > 0.0 ? P.cellWalkDepth : 32.0;
  gInterpolation = VS_SPEC_INTERPOLATION;
  if (VS_SPEC_SURFACE != 0u)
    surface_load();
  gLightCount = VS_SPEC_LIGHTS != 0u ? min(P.lightCount, VS_MAX_SCENE_LIGHTS) : 0u;
  if (VS_SPEC_LIGHTS != 0u)
    gIndexToWorld = inverse(P.volume.worldToIndex);
  vs_set_cropping(P.volume.cropLo, P.volume.cropHi, VS_SPEC_CROPPING != 0u ? P.volume.cropFlags : 0u);
#ifndef VS_NO_GRID
  uvec4 cellHash = vs_pcg4d(uvec4(pix, gSeed, 0xce11u));
  gCellU = vec3(vs_unit_float(cellHash.x), vs_unit_float(cellHash.y), vs_unit_float(cellHash.z));
#endif
  uint idx = inside ? pix.y * W + pix.x : 0u;
  float depth = inside ? uDepth[idx] : 1.0;

  Accumulator acc;
  acc.sum = inside ? uSum[idx] : vec4(0.0);
  acc.comp = inside ? uComp[idx] : vec4(0.0);
  acc.sq = inside ? uSq[idx] : vec4(0.0);
  uint done = inside ? uCount[idx] : pc.target;

  /* Samples until the pixel holds pc.target, while the group's back-edges (an upper bound, the
   * same in every lane: each loop runs as long as its longest lane) leave room for one more
   * sample at its most expensive. */
  uint scatterCost = scatter_cost(gStrategy, P.grid.side, P.environmentLevels, VS_SPEC_CELL_MODE);
  /* Full transport: the continuation's phase sample and its light pdf (the strategy's descents again). */
  if (VS_SPEC_PATH != 0u)
    scatterCost += 16u + 2u * P.environmentLevels + 2u * P.grid.side + 8u;
  if (VS_SPEC_LIGHTS != 0u)
    scatterCost += gLightCount + 4u; /* issue 38: the lights' loop (their shadow rays count as rays below) */
  Path path = path_idle();
  if (VS_SPEC_PATH != 0u && inside)
    path = path_load(idx);
  /* Per shadow ray: its direction (the map is made once: counted in the first) and its clip planes. */
  uint perRay = 16u + 2u * P.environmentLevels + 6u + 4u;
  /* The shadow rays of a sample share the steps the budget leaves after the rest of its worst
   * case, each ray at most VS_TRACKING_CAP: up to 6 rays keep that cap each (the budget holds them),
   * more share it so that one sample always fits (64 rays: ~800 steps each if all need them; a ray
   * that reaches its cap scores transmittance 0, as at VS_TRACKING_CAP). */
  /* issue 38: each of VTK's lights is one more shadow ray per event (scene_lights.glsl). */
  uint eventRays = gShadowRays + gLightCount;
  uint sampleFixed = VS_TRACKING_CAP + 1u + scatterCost + eventRays * (1u + perRay) + VS_START_COST + VS_SAMPLE_SLACK;
  gShadowBudget = min(eventRays * VS_TRACKING_CAP, VS_SPEC_LOOP_BUDGET - min(sampleFixed + eventRays, VS_SPEC_LOOP_BUDGET));
  uint sampleMax = sampleFixed + gShadowBudget;
  uint cost = 0u;
  uint events = 0u; /* scattering events of this invocation's paths (full transport) */
  while (subgroupAny(done < pc.target) && cost + sampleMax <= VS_SPEC_LOOP_BUDGET)
  {
    uint cameraCost = 0u, shadowCost = 0u;
    bool scattered = false;
    if (done < pc.target)
    {
      if (VS_SPEC_PATH == 0u)
      {
        accumulate(acc, render_sample(pix, done, depth, perRay, cameraCost, shadowCost, scattered));
        done += 1u;
      }
      else
      {
        if (path_segment(pix, done, depth, perRay, path, cameraCost, shadowCost, scattered))
        {
          accumulate(acc, path.L);
          done += 1u;
        }
        events += scattered ? 1u : 0u;
      }
    }
#ifdef VS_COUNT_LOOKUPS
    /* SIMD occupancy of the tracking loops: the steps the lanes needed against the steps their
     * group ran (as long as its longest lane), times the lanes. */
    gLaneSteps += cameraCost + shadowCost;
    uint groupSteps = subgroupMax(cameraCost) + subgroupMax(shadowCost);
    if (subgroupElect())
      gGroupLaneSteps += groupSteps * gl_SubgroupSize;
#endif
    cost += 1u + VS_START_COST + VS_SAMPLE_SLACK + subgroupMax(cameraCost) + subgroupMax(shadowCost) +
      (subgroupAny(scattered) ? scatterCost : 0u);
  }

  if (inside)
  {
    uSum[idx] = acc.sum;
    uComp[idx] = acc.comp;
    uSq[idx] = acc.sq;
    uCount[idx] = done;
    if (VS_SPEC_PATH != 0u)
      path_store(idx, path);
    if (done < pc.target)
      atomicAdd(uCount[W * H], 1u);
  }
  /* The scattering events of the dispatch (full transport), after the short count: what the host
   * reports as events per path. One atomic per SIMD group. */
  if (VS_SPEC_PATH != 0u)
  {
    uint groupEvents = subgroupAdd(events);
    if (subgroupElect())
      atomicAdd(uCount[W * H + 1u], groupEvents);
  }
#ifdef VS_COUNT_LOOKUPS
  atomicAdd(uLookups[0], gLookups.x);
  atomicAdd(uLookups[1], gLookups.y);
  atomicAdd(uLookups[2], gLookups.z);
  atomicAdd(uLookups[3], gLaneSteps);
  atomicAdd(uLookups[4], gGroupLaneSteps);
  atomicAdd(uLookups[5], gShadowRaysCast);
  atomicAdd(uLookups[6], gShadowRaysBlocked);
#endif
}
