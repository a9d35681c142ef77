/*
 * mc_render.glsl — unbiased progressive Monte Carlo single scattering under
 * environment light (von Radziewsky et al. 2017, Sec. 4 and 7). Included by mc_render_<format>.comp,
 * which defines VS_VIS_FORMAT (the visibility grid's storage format).
 *
 * Per sample: a jittered camera ray; free-flight distance by delta tracking against
 * the majorant bricks (empty bricks skipped); at a real collision, one direction from
 * the strategy (Uniform, Environment, Visibility, Combined or TwoStep), its
 * transmittance to the box by ratio tracking, and
 *     L = albedo * (1/4pi) * T * L_env(w) / pdf(w).
 * The approximate visibility only shapes the pdf; T is the true transmittance, which
 * keeps the estimator unbiased. Escaping rays see the environment (or are transparent,
 * so VTK's background shows); rays reaching the opaque depth are transparent.
 * Accumulates compensated (Kahan) sums of (rgb, alpha) and their squares per pixel;
 * one dispatch adds `sampleCount` samples per pixel, from sample `sampleOffset` of the frame.
 */
#include "octahedral.h"
#include "render_params.h"
#include "rng.h"
#include "strategies.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, r32f) uniform readonly image3D uVolume;
layout(std430, binding = 1) readonly buffer TransferFunction { vec4 uTF[]; };
layout(binding = 2, r32f) uniform readonly image3D uMajorant;
layout(binding = 3, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = 4) readonly buffer Params { VsRenderParams P; };
layout(std430, binding = 5) readonly buffer EnvRadiance { vec4 uEnv[]; };
layout(std430, binding = 6) readonly buffer EnvMips { float uMips[]; };
layout(std430, binding = 7) readonly buffer Depth { float uDepth[]; };
layout(std430, binding = 8) buffer Sum { vec4 uSum[]; };
layout(std430, binding = 9) buffer Compensation { vec4 uComp[]; };
layout(std430, binding = 10) buffer Squares { vec4 uSq[]; };
layout(push_constant) uniform Push { uint sampleOffset; uint sampleCount; } pc;

/* The instrumented variant (mc_render_count.comp) counts what a sample reads:
 * uLookups[0] trilinear volume samples, [1] majorant-brick loads, [2] visibility texels. */
#ifdef VS_COUNT_LOOKUPS
layout(std430, binding = 11) buffer Lookups { uint uLookups[]; };
uvec3 gLookups = uvec3(0u);
#define VS_COUNT(i) (gLookups[i]++)
#else
#define VS_COUNT(i)
#endif

float vs_env_mip(uint index)
{
  return uMips[index];
}

#include "volume_access.glsl"

/* Registers, loaded once per invocation (lavapipe does not hoist buffer loads). */
ivec3 gDims;
ivec3 gBricks;
float gBrickSize;
vec4 gTF;
uint gEnvSize;
uint gClipCount;
uint gStrategy;
float gRefineDepth;
uint gInterpolation; /* interpolation.h: the scalar's reconstruction (P.tracking.y) */
/* The direction map of this sample (D x D <= 256 values), which the strategies read through
 * vs_map_value (vs_prelude.h): one module-scope array, never copied into calls. */
float gValues[256];

float vs_map_value(uint n)
{
  return gValues[n];
}

vec3 env_radiance(vec3 w)
{
  uvec2 t = vs_dir_to_texel(w, gEnvSize);
  return uEnv[t.y * gEnvSize + t.x].rgb * P.sampling2.y;
}

/* The environment seen directly (the background): bilinear between texels, so that it does not
 * look blocky when a texel spans several pixels. */
vec3 env_radiance_display(vec3 w)
{
  vec2 uv = vs_dir_to_octa(w);
  vec3 sum = vec3(0.0);
  for (uint c = 0u; c < 4u; ++c)
  {
    float weight;
    uvec2 t = vs_octa_bilinear_texel(uv, gEnvSize, c, weight);
    sum += weight * uEnv[t.y * gEnvSize + t.x].rgb;
  }
  return sum * P.sampling2.y;
}

float brick_majorant(ivec3 b)
{
  VS_COUNT(1);
  return imageLoad(uMajorant, clamp(b, ivec3(0), gBricks - 1)).r;
}

/* The shortest step the trackers take from t: ~16 ulps of t (or 2e-6 voxel), so t + step > t. */
float min_step(float t, vec3 d)
{
  return 2e-6 * max(abs(t), 1.0 / max(length(d), 1e-20));
}

/* The brick the ray o + t d is in just after t (at t + half the shortest step: a brick and a cell
 * are picked at the same point), and the distance t where it leaves it (at least the shortest step
 * on: a sliver of the previous brick shorter than float resolves may go with this one). */
ivec3 brick_at(vec3 o, vec3 d, float t, out float tExit)
{
  float h = min_step(t, d);
  vec3 p = o + t * d;
  vec3 probe = o + (t + 0.5 * h) * d;
  ivec3 b = ivec3(floor(probe / gBrickSize));
  vec3 lo = vec3(b) * gBrickSize, hi = lo + gBrickSize;
  float e = 1e30;
  for (int i = 0; i < 3; ++i)
  {
    if (d[i] > 1e-20)
      e = min(e, (hi[i] - p[i]) / d[i]);
    else if (d[i] < -1e-20)
      e = min(e, (lo[i] - p[i]) / d[i]);
  }
  /* Always move forward, even when rounding put p on the far side of a face. */
  tExit = t + max(e, h);
  return b;
}

/* The exponential free-flight distance of rate mu for a uniform u in [0,1). */
float sample_exponential(float u, float mu)
{
  return -log(1.0 - u) / mu;
}

/* Trilinear interpolation inside one voxel cell: corners c0 = (000, 100, 010, 110),
 * c1 = (001, 101, 011, 111), local coordinates f in [0,1]^3. */
float cell_trilinear(vec4 c0, vec4 c1, vec3 f)
{
  vec4 z = mix(c0, c1, f.z);
  vec2 y = mix(z.xy, z.zw, f.y);
  return mix(y.x, y.y, f.x);
}

/* The largest extinction on the ray segment [ta, tb] inside the voxel cell `lo`: a trilinear
 * interpolant takes its extremes over a box at the box's corners, so the scalars of the segment lie
 * between the smallest and largest interpolant at the 8 corners of its bounding box. */
float segment_max_extinction(vec3 o, vec3 d, float ta, float tb, ivec3 lo, vec4 c0, vec4 c1)
{
  vec3 top = vec3(gDims - 1);
  vec3 fa = clamp(clamp(o + ta * d, vec3(0.0), top) - vec3(lo), 0.0, 1.0);
  vec3 fb = clamp(clamp(o + tb * d, vec3(0.0), top) - vec3(lo), 0.0, 1.0);
  vec3 f0 = min(fa, fb), f1 = max(fa, fb);
  if (gInterpolation == VS_INTERPOLATION_NEAREST)
    return vs_nearest_max_extinction(f0, f1, c0, c1, gTF); /* the corners whose halves it reaches */
  float smin = 3.4e38, smax = -3.4e38;
  for (uint k = 0u; k < 8u; ++k)
  {
    vec3 f = vec3((k & 1u) != 0u ? f1.x : f0.x, (k & 2u) != 0u ? f1.y : f0.y, (k & 4u) != 0u ? f1.z : f0.z);
    float v = cell_trilinear(c0, c1, f);
    smin = min(smin, v);
    smax = max(smax, v);
  }
  return vs_max_extinction(smin, smax, gTF);
}

/* A brick whose majorant segment is optically thick (mu * length > gRefineDepth: a dense medium, or a
 * tiny unit distance) is walked in voxel cells instead, with the majorant of the sub-segment
 * [t, tNext) of the current cell: the longest sub-segment whose optical depth at its own majorant
 * stays below gRefineDepth (bisection in log length), or the shortest step float resolves. So the
 * trackers take O(optical depth) steps, never O(brick majorant x length): at an extinction of 1e9
 * per voxel the brick majorant would ask for 1e9 null collisions per voxel, at steps float cannot add
 * to t. The segments start where the previous one ended, so the majorant is a fixed function of
 * the ray and the estimators stay unbiased. */
float refine_majorant(vec3 o, vec3 d, float t, inout float tNext, float mu)
{
  float hMin = min_step(t, d);
  vec3 p = o + t * d;
  ivec3 lo = clamp(ivec3(floor(o + (t + 0.5 * hMin) * d)), ivec3(0), max(gDims - 2, ivec3(0)));
  ivec3 hi = min(lo + 1, gDims - 1);
  float e = 1e30;
  for (int i = 0; i < 3; ++i)
  {
    /* The cell's faces, except the volume's outer ones: scalars clamp beyond them. */
    if (d[i] > 1e-20 && lo[i] + 1 < gDims[i] - 1)
      e = min(e, (float(lo[i] + 1) - p[i]) / d[i]);
    else if (d[i] < -1e-20 && lo[i] > 0)
      e = min(e, (float(lo[i]) - p[i]) / d[i]);
  }
  if (gInterpolation == VS_INTERPOLATION_NEAREST)
    e = min(e, vs_nearest_midplane_exit(p, d, lo)); /* segments end where the nearest voxel changes */
  float hMax = min(tNext - t, max(e, hMin));
  vec4 c0 = vec4(imageLoad(uVolume, ivec3(lo.x, lo.y, lo.z)).r, imageLoad(uVolume, ivec3(hi.x, lo.y, lo.z)).r,
    imageLoad(uVolume, ivec3(lo.x, hi.y, lo.z)).r, imageLoad(uVolume, ivec3(hi.x, hi.y, lo.z)).r);
  vec4 c1 = vec4(imageLoad(uVolume, ivec3(lo.x, lo.y, hi.z)).r, imageLoad(uVolume, ivec3(hi.x, lo.y, hi.z)).r,
    imageLoad(uVolume, ivec3(lo.x, hi.y, hi.z)).r, imageLoad(uVolume, ivec3(hi.x, hi.y, hi.z)).r);
  VS_COUNT(0);
  if (gInterpolation != VS_INTERPOLATION_NEAREST && (any(isnan(c0)) || any(isnan(c1))))
  {
    /* A NaN corner makes every trilinear sample of the cell NaN: empty space (volume_access.glsl). */
    tNext = t + hMax;
    return 0.0;
  }
  float m = segment_max_extinction(o, d, t, t + hMax, lo, c0, c1);
  float h = hMax;
  if (m * h > gRefineDepth)
  {
    /* m(h) h grows with h: bisect for the longest h that keeps it below the depth. */
    float hLo = hMin, hHi = hMax;
    float mLo = segment_max_extinction(o, d, t, t + hLo, lo, c0, c1);
    for (int k = 0; k < 12 && hHi > 1.01 * hLo; ++k)
    {
      float hMid = sqrt(hLo * hHi);
      float mMid = segment_max_extinction(o, d, t, t + hMid, lo, c0, c1);
      if (mMid * hMid <= gRefineDepth)
      {
        hLo = hMid;
        mLo = mMid;
      }
      else
        hHi = hMid;
    }
    h = hLo;
    m = mLo;
  }
  tNext = t + h;
  /* The brick majorant bounds the cell too (up to rounding at brick faces). */
  return min(m, mu);
}

/* The majorant segment of the ray from t: returns mu and sets tNext, with mu >= the extinction
 * on [t, tNext). One walk for delta tracking and ratio tracking. */
float majorant_segment(vec3 o, vec3 d, float t, float tEnd, out float tNext)
{
  float tExit;
  ivec3 b = brick_at(o, d, t, tExit);
  tNext = min(tExit, tEnd);
  float mu = brick_majorant(b);
  if (mu * (tNext - t) > gRefineDepth)
    mu = refine_majorant(o, d, t, tNext, mu);
  return mu;
}

/* Null collisions one tracking call may take before it gives up: only reached where float
 * cannot resolve the medium (a majorant segment at the shortest step still has a huge optical
 * depth but the sampled points keep missing it); it then treats the medium as opaque. */
const uint VS_MAX_TRACKING_STEPS = 65536u;

/* Delta tracking on [t0, t1): true at a real collision (tHit, its albedo). Distances inside a
 * segment count from its start, so steps far below the resolution of t still add up. */
bool delta_track(vec3 o, vec3 d, float t0, float t1, inout VsRng rng, out float tHit, out vec3 albedo)
{
  float t = t0;
  uint steps = 0u;
  while (t < t1)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    if (mu > 0.0)
    {
      float h = tNext - t;
      float dt = 0.0;
      while (true)
      {
        dt += sample_exponential(vs_rng_float(rng), mu);
        if (dt >= h)
          break;
        VS_COUNT(0);
        vec4 c = vs_classify(vs_sample(o + (t + dt) * d, gDims, gInterpolation), gTF);
        if (vs_rng_float(rng) * mu < c.w || ++steps >= VS_MAX_TRACKING_STEPS)
        {
          tHit = t + dt;
          albedo = c.rgb;
          return true;
        }
      }
    }
    t = tNext;
  }
  return false;
}

/* Ratio tracking of the transmittance on [t0, t1), with Russian roulette once it is small. */
float ratio_track(vec3 o, vec3 d, float t0, float t1, inout VsRng rng)
{
  float T = 1.0;
  float t = t0;
  uint steps = 0u;
  while (t < t1)
  {
    float tNext;
    float mu = majorant_segment(o, d, t, t1, tNext);
    if (mu > 0.0)
    {
      float h = tNext - t;
      float dt = 0.0;
      while (true)
      {
        dt += sample_exponential(vs_rng_float(rng), mu);
        if (dt >= h)
          break;
        VS_COUNT(0);
        float sigma = vs_classify(vs_sample(o + (t + dt) * d, gDims, gInterpolation), gTF).w;
        T *= max(0.0, 1.0 - sigma / mu);
        if (++steps >= VS_MAX_TRACKING_STEPS)
          return 0.0;
        if (T < 0.05)
        {
          if (vs_rng_float(rng) < 0.5)
            return 0.0;
          T *= 2.0;
        }
      }
    }
    t = tNext;
  }
  return T;
}

/* The ray interval inside the (cropped) box and the kept side of every clip plane. */
vec2 ray_interval(vec3 o, vec3 d)
{
  return vs_clip_planes(o, d, vs_intersect_box(o, d, P.boxMin.xyz, P.boxMax.xyz), P.clipPlanes, gClipCount);
}

float visibility_texel(uvec3 cell, uint n, uint D)
{
  ivec3 t = ivec3(int(cell.x * D + n % D), int(cell.y * D + n / D), int(cell.z));
  VS_COUNT(2);
  return imageLoad(uVisibility, t).r;
}

/* The D x D values the strategy warps at index-space point x: visibility (+ epsilon),
 * times the environment's importance at level log2(D) for Combined and TwoStep. */
void direction_values(vec3 x, uint strategy, uint D, inout VsRng rng)
{
  uvec3 cells = P.grid.xyz;
  vec3 c = (x - P.boxMin.xyz) / P.cellSize.xyz - 0.5;
  c = clamp(c, vec3(0.0), vec3(cells - 1u));
  uvec3 c0 = uvec3(floor(c));
  uvec3 c1 = min(c0 + 1u, cells - 1u);
  vec3 f = c - vec3(c0);
  uint DD = D * D;
  for (uint n = 0u; n < DD; ++n)
    gValues[n] = 0.0;
  if (P.sampling.z == VS_CELL_STOCHASTIC)
  {
    /* One corner with probability equal to its trilinear weight. */
    vec3 u = vec3(vs_rng_vec2(rng), vs_rng_float(rng));
    uvec3 cell = uvec3(u.x < f.x ? c1.x : c0.x, u.y < f.y ? c1.y : c0.y, u.z < f.z ? c1.z : c0.z);
    for (uint n = 0u; n < DD; ++n)
      gValues[n] = visibility_texel(cell, n, D);
  }
  else
  {
    for (uint k = 0u; k < 8u; ++k)
    {
      uvec3 cell = uvec3((k & 1u) != 0u ? c1.x : c0.x, (k & 2u) != 0u ? c1.y : c0.y, (k & 4u) != 0u ? c1.z : c0.z);
      float w = ((k & 1u) != 0u ? f.x : 1.0 - f.x) * ((k & 2u) != 0u ? f.y : 1.0 - f.y) *
        ((k & 4u) != 0u ? f.z : 1.0 - f.z);
      if (w > 0.0)
        for (uint n = 0u; n < DD; ++n)
          gValues[n] += w * visibility_texel(cell, n, D);
    }
  }
  uint level = vs_log2(D);
  for (uint n = 0u; n < DD; ++n)
  {
    float v = gValues[n] + P.sampling2.x;
    gValues[n] = strategy == VS_STRATEGY_VISIBILITY ? v : v * vs_env_node(level, uvec2(n % D, n / D));
  }
}

vec3 sample_direction(vec3 x, uint strategy, inout VsRng rng, out float pdf)
{
  uint K = P.sampling.w;
  uint D = P.grid.w;
  if (strategy == VS_STRATEGY_ENVIRONMENT)
    return vs_sample_environment(K, vs_rng_vec2(rng), pdf);
  if (strategy == VS_STRATEGY_UNIFORM || D == 0u)
    return vs_sample_uniform(vs_rng_vec2(rng), pdf);
  direction_values(x, strategy, D, rng);
  return vs_sample_direction(strategy, D, K, vs_rng_vec2(rng), pdf);
}

/* The compensated per-pixel accumulators, held in registers across the samples of a dispatch
 * (loaded once, stored once). Kahan summation: the sum stays exact to float precision over 1e5+
 * samples. The same additions in the same order as one sample per dispatch, so a fixed seed gives
 * the same bits for any split of the samples into frames and dispatches. */
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
  float scale = P.sampling2.w > 0.0 ? P.sampling2.w : 1.0;
  vec4 w = v * vec4(scale, scale, scale, 1.0);
  acc.sq += w * w;
}

/* One path of pixel `pix`: sample `sampleIndex` of the image (its random numbers depend on the
 * pixel, the sample index and the seed only). Returns (rgb, alpha). */
vec4 render_sample(uvec2 pix, uint sampleIndex, float depth)
{
  uint W = P.viewport.x, H = P.viewport.y;
  VsRng rng = vs_rng_init(pix, sampleIndex, P.viewport.w);
  vec2 jitter = vs_rng_vec2(rng);
  vec2 ndc = (vec2(pix) + jitter) / vec2(W, H) * 2.0 - 1.0;
  vec4 pn = P.invViewProj * vec4(ndc, -1.0, 1.0);
  vec4 pf = P.invViewProj * vec4(ndc, 1.0, 1.0);
  vec3 ow = pn.xyz / pn.w;
  vec3 dw = normalize(pf.xyz / pf.w - ow);
  float tDepth = 1e30;
  if (depth < 1.0)
  {
    vec4 pd = P.invViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    tDepth = dot(pd.xyz / pd.w - ow, dw);
  }
  vec3 o = (P.worldToIndex * vec4(ow, 1.0)).xyz;
  vec3 d = (P.worldToIndex * vec4(dw, 0.0)).xyz;
  vec2 ti = ray_interval(o, d);
  float t0 = max(ti.x, 0.0), t1 = min(ti.y, tDepth);

  vec4 result = vec4(0.0);
  float tHit;
  vec3 albedo;
  if (t0 < t1 && delta_track(o, d, t0, t1, rng, tHit, albedo))
  {
    result.a = 1.0;
    if (any(greaterThan(albedo, vec3(0.0))))
    {
      vec3 x = o + tHit * d;
      float pdf;
      vec3 w = sample_direction(x, gStrategy, rng, pdf);
      if (pdf > 0.0)
      {
        vec3 Le = env_radiance(w);
        if (any(greaterThan(Le, vec3(0.0))))
        {
          vec3 di = (P.worldToIndex * vec4(w, 0.0)).xyz;
          vec2 ts = ray_interval(x, di);
          float T = ratio_track(x, di, 0.0, ts.y, rng);
          result.rgb = albedo * VS_INV_4PI * T * Le / pdf;
        }
      }
    }
  }
  else if (tDepth >= 1e30 && P.background.w > 0.5)
  {
    result = vec4(env_radiance_display(dw), 1.0);
  }
  /* Non-finite contributions (should not happen) are dropped rather than poisoning the pixel. */
  if (any(isnan(result)) || any(isinf(result)))
    result = vec4(0.0);
  return result;
}

void main()
{
  uvec2 pix = gl_GlobalInvocationID.xy;
  uint W = P.viewport.x, H = P.viewport.y;
  if (pix.x >= W || pix.y >= H)
    return;
  gDims = ivec3(P.dims.xyz);
  gBricks = ivec3(P.bricks.xyz);
  gBrickSize = P.sampling2.z;
  gTF = P.tf;
  gEnvSize = 1u << P.sampling.w;
  gClipCount = P.bricks.w;
  gStrategy = P.sampling.x;
  gRefineDepth = P.tracking.x > 0.0 ? P.tracking.x : 32.0;
  gInterpolation = uint(P.tracking.y);
  vs_set_cropping(P.cropLo, P.cropHi, P.crop.x);
  uint idx = pix.y * W + pix.x;
  float depth = uDepth[idx];

  /* pc.sampleCount samples per dispatch, samples sampleOffset.. of the frame. */
  Accumulator acc;
  acc.sum = uSum[idx];
  acc.comp = uComp[idx];
  acc.sq = uSq[idx];
  uint first = P.viewport.z + pc.sampleOffset;
  for (uint s = 0u; s < pc.sampleCount; ++s)
    accumulate(acc, render_sample(pix, first + s, depth));
  uSum[idx] = acc.sum;
  uComp[idx] = acc.comp;
  uSq[idx] = acc.sq;
#ifdef VS_COUNT_LOOKUPS
  atomicAdd(uLookups[0], gLookups.x);
  atomicAdd(uLookups[1], gLookups.y);
  atomicAdd(uLookups[2], gLookups.z);
#endif
}
