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
 * the volume's coverage: P.background.w = 2) or are transparent, so VTK's background shows; rays
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
 */
#include "brick_walk.h"
#include "octahedral.h"
#ifdef VS_RAY_MARCHING
#include "ray_marching.h"
#endif
#include "render_params.h"
#include "rng.h"
#include "sobol.h"
#include "strategies.h"
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

/* Specialization constants: the host compiles one pipeline per combination it renders with, so the
 * code of the other strategies, the other cell mode and (where no brick is optically thick) the
 * cell walk is gone. That matters on lavapipe, which runs both sides of every `if` (masked) and
 * every loop body at least once: such code costs as if it were always taken. */
layout(constant_id = 0) const uint VS_SPEC_STRATEGY = 4u;  /* VS_STRATEGY_*, = params.sampling.x */
layout(constant_id = 1) const uint VS_SPEC_CELL_MODE = 1u; /* VS_CELL_*, = params.sampling.z */
layout(constant_id = 2) const uint VS_SPEC_REFINE = 1u;    /* 0: no majorant segment reaches the refinement depth */
layout(constant_id = 3) const uint VS_SPEC_CAMERA = 0u;    /* VS_CAMERA_*, = params.tracking.z */
layout(constant_id = 4) const uint VS_SPEC_INTERPOLATION = 0u; /* interpolation.h, = params.tracking.w */
layout(constant_id = 5) const uint VS_SPEC_CROPPING = 0u;  /* 1: cropping regions (params.crop.x != 0) */
layout(constant_id = 7) const uint VS_SPEC_DEFENSIVE = 0u; /* 1: TwoStep mixed with Environment sampling (P.mixture.x) */
layout(constant_id = 8) const uint VS_SPEC_SKIP = 1u;      /* 1: empty space is crossed in one step (binding 13) */
layout(constant_id = 9) const uint VS_SPEC_QUADS = 0u;     /* 1: trilinear samples read the volume's 8-bit quads
                                                             (binding 15, vsDeviceVolume.h) */
layout(constant_id = 11) const uint VS_SPEC_SAMPLER = 0u;   /* VS_SAMPLER_* (render_params.h), = params.crop.z */
const bool VS_SPEC_SOBOL = VS_SPEC_SAMPLER == VS_SAMPLER_SOBOL;
layout(constant_id = 10) const uint VS_SPEC_CONTROL = 0u;   /* VS_CONTROL_* bits (render_params.h): the trackers
                                                              split the extinction into the brick's control (uBricks.y) and the rest */
layout(constant_id = 13) const uint VS_SPEC_TRANSMITTANCE = 0u; /* VS_TRANSMITTANCE_* (render_params.h): the shadow
                                                              rays' estimator, = params.mixture.y */
layout(constant_id = 12) const uint VS_SPEC_FACTOR = 0u;   /* 1: the extinction is scaled by the volume's factor
                                                              (the gradient opacity, binding 16; = params.crop.w) */
layout(constant_id = 6) const uint VS_SPEC_TABLE = 0u;     /* 1: the grid strategies read the cell's direction
                                                             table (binding 12), stochastic cell only */
layout(binding = 0, r32f) uniform readonly image3D uVolume;
#define VS_TF_TEXELS
layout(binding = 1) uniform samplerBuffer uTF;
layout(binding = 2, rgba32f) uniform readonly image3D uBricks; /* per brick: majorant, control, empty distance, 0
                                                                  (vsMajorantGrid.h TrackingImage) */
layout(binding = 3, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = 4) readonly buffer Params { VsRenderParams P; };
/* Tables read at per-lane indices are texel buffers: lavapipe loads them with vector gathers, and
 * a storage buffer with a scalar loop over the SIMD lanes (measured: ~15% of the kernel's time). */
layout(binding = 5) uniform samplerBuffer uEnv;  /* rgba32f: the environment's radiance per texel */
layout(binding = 6) uniform samplerBuffer uMips; /* r32f: its luminance mip pyramid */
layout(std430, binding = 7) readonly buffer Depth { float uDepth[]; };
layout(std430, binding = 8) buffer Sum { vec4 uSum[]; };
layout(std430, binding = 9) buffer Compensation { vec4 uComp[]; };
layout(std430, binding = 10) buffer Squares { vec4 uSq[]; };
/* Samples each pixel holds (W x H), then one counter of the pixels a dispatch left short of target. */
layout(std430, binding = 11) buffer Progress { uint uCount[]; };
/* The direction table (shared/direction_table.h): per cell, the shares of its map's quadtree nodes. */
layout(binding = 12) uniform usamplerBuffer uTable; /* r32ui */
/* An integer-coded volume's quads: texel (x, y, z) packs the 8-bit codes of voxels (x, y), (x + 1, y),
 * (x, y + 1), (x + 1, y + 1) of slice z; the scalar is code + P.dims.w. */
layout(binding = 15, r32ui) uniform readonly uimage3D uQuads;
/* The extinction factor per voxel (vsDeviceVolume.h; read only with VS_SPEC_FACTOR). */
layout(binding = 16, r32f) uniform readonly image3D uFactor;
#define VS_FACTOR_IMAGE
layout(push_constant) uniform Push { uint target; } pc;

/* The instrumented variant (mc_render_count.comp) counts what a sample reads:
 * uLookups[0] trilinear volume samples, [1] majorant-brick loads, [2] visibility texels (or table nodes),
 * and how busy the SIMD lanes are: [3] the tracking steps the lanes took, [4] the steps their
 * subgroups ran times the subgroup's size. */
#ifdef VS_COUNT_LOOKUPS
layout(std430, binding = 14) buffer Lookups { uint uLookups[]; };  /* binding 15: uQuads */
uvec3 gLookups = uvec3(0u);
uint gLaneSteps = 0u, gGroupLaneSteps = 0u;
#define VS_COUNT(i) (gLookups[i]++)
#else
#define VS_COUNT(i)
#endif

#define VS_DIRECTION_SOURCE(n) P.directionSources[(n) / 4u][(n) % 4u]

float vs_env_mip(uint index)
{
  return texelFetch(uMips, int(index)).r;
}

#include "volume_access.glsl"
#ifndef VS_NO_GRID
#include "direction_map.glsl"
#endif

/* Parameters the per-sample code reads, loaded once per invocation in main(): lavapipe loads a
 * storage-buffer value inside code that not every lane runs with a scalar loop over the lanes
 * (one masked load per lane), even at a uniform address (measured in its machine code). */
float gEnvScale;    /* P.sampling2.y: the environment's intensity */
float gEpsilon;     /* P.sampling2.x */
float gSquareScale; /* P.sampling2.w */
float gMixture;     /* P.mixture.x */
uint gEnvLevels;    /* P.sampling.w */
vec3 gBoxMin, gBoxMax, gCellSize;
uvec4 gGrid;
uvec4 gViewport;
bool gBackgroundVisible;
/* The alpha of a camera ray that escapes to the environment: 1 (P.background.w = 1, the image is
 * opaque) or 0 (w = 2: the radiance still includes the environment seen through the volume, but the
 * alpha is the volume's coverage, so the host can composite it over a background it draws itself). */
float gEscapeAlpha;
mat4 gWorldToIndex, gInvViewProj;
vec4 gClipPlanes[VS_MAX_CLIP_PLANES == 8u ? 8 : -1]; /* main() copies 8 */

/* Registers, loaded once per invocation (lavapipe does not hoist buffer loads). */
ivec3 gDims;
ivec3 gBricks;
float gBrickSize;
vec4 gTF;
uint gEnvSize;
uint gClipCount;
uint gStrategy;
float gInvBrickSize;
/* The ray being tracked (one at a time: the camera ray, then the shadow rays): what the majorant
 * walk needs of it per segment, computed once per ray. */
struct RayConstants
{
  vec3 invD;       /* 1 / d per axis (inf where d is 0: masked where used) */
  float walkScale; /* the brick walk's shortest step scale (brick_walk.h vs_walk_scale) */
};
RayConstants gRay;

void set_ray(vec3 o, vec3 d)
{
  gRay.invD = 1.0 / d;
  gRay.walkScale = vs_walk_scale(o, d);
}
uint gShadowRays;
uint gShadowBudget; /* tracking steps the shadow rays of one sample share (main) */
uint gTableBase; /* where the scatter cell's direction table starts (VS_SPEC_TABLE) */
/* The stochastic cell pick's numbers: the pixel's own, the same for all its samples (main).
 * Each pick is unbiased whatever the numbers (the sample is scored with the pdf of the cell it
 * warped through), and a pixel whose samples warp through one cell's table keeps the Sobol
 * sequence's strata of its light directions: 2% lower MSE at 256 spp (docs/benchmarks.md). */
vec3 gCellU;

uint vs_table_value(uint i)
{
  VS_COUNT(2);
  return texelFetch(uTable, int(i)).r;
}
float gRefineDepth;
uint gInterpolation; /* interpolation.h: the scalar's reconstruction (P.tracking.w) */
vec3 env_radiance(vec3 w)
{
  uvec2 t = vs_dir_to_texel(w, gEnvSize);
  return texelFetch(uEnv, int(t.y * gEnvSize + t.x)).rgb * gEnvScale;
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
    sum += weight * texelFetch(uEnv, int(t.y * gEnvSize + t.x)).rgb;
  }
  return sum * gEnvScale;
}

/* Brick b's majorant, control extinction (<= every sample's) and empty-space distance (0, or where
 * the majorant is 0 the chessboard distance in bricks to the nearest brick whose majorant is not:
 * vsEmptySpaceDistance.h); b clamps to the grid. */
vec3 brick_walk_values(ivec3 b)
{
  VS_COUNT(1);
  return imageLoad(uBricks, clamp(b, ivec3(0), gBricks - 1)).xyz;
}

/* The kernel's hot paths are written without constant-length loops: lavapipe's loop limiter counts
 * every back-edge (see the top of this file), and a loop the compiler keeps would cost budget. */

/* The distance along d from p to the face ahead of the voxel cell from lo to lo + 1 on one axis,
 * except the volume's outer faces (of `dim` voxels): scalars clamp beyond them (1e30: none). */
float cell_face_distance(float p, float d, int lo, int dim)
{
  if (d > 1e-20)
    return lo + 1 < dim - 1 ? (float(lo + 1) - p) / d : 1e30;
  if (d < -1e-20)
    return lo > 0 ? (float(lo) - p) / d : 1e30;
  return 1e30;
}

/* Where the ray o + t d leaves the cube of bricks [b - r, b + r] (r >= 0 bricks; r = 0: brick b),
 * at least the shortest step on (brick_walk.h). */
float brick_cube_exit(vec3 o, vec3 d, float t, ivec3 b, float r)
{
  return vs_brick_cube_exit(o, d, gRay.invD, t, vs_walk_min_step(t, gRay.walkScale), b, r, gBrickSize);
}

/* The brick the ray o + t d is in just after t (a brick and a cell are picked at the same point),
 * and the distance t where it leaves it (brick_walk.h). */
ivec3 brick_at(vec3 o, vec3 d, float t, out float tExit)
{
  float h = vs_walk_min_step(t, gRay.walkScale);
  ivec3 b = vs_brick_after(o, d, t, h, gInvBrickSize);
  tExit = vs_brick_cube_exit(o, d, gRay.invD, t, h, b, 0.0, gBrickSize);
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
  /* The 8 corners of the box [f0, f1], unrolled. */
  float v0 = cell_trilinear(c0, c1, vec3(f0.x, f0.y, f0.z)), v1 = cell_trilinear(c0, c1, vec3(f1.x, f0.y, f0.z));
  float v2 = cell_trilinear(c0, c1, vec3(f0.x, f1.y, f0.z)), v3 = cell_trilinear(c0, c1, vec3(f1.x, f1.y, f0.z));
  float v4 = cell_trilinear(c0, c1, vec3(f0.x, f0.y, f1.z)), v5 = cell_trilinear(c0, c1, vec3(f1.x, f0.y, f1.z));
  float v6 = cell_trilinear(c0, c1, vec3(f0.x, f1.y, f1.z)), v7 = cell_trilinear(c0, c1, vec3(f1.x, f1.y, f1.z));
  float smin = min(min(min(v0, v1), min(v2, v3)), min(min(v4, v5), min(v6, v7)));
  float smax = max(max(max(v0, v1), max(v2, v3)), max(max(v4, v5), max(v6, v7)));
  return vs_max_extinction(smin, smax, gTF);
}

/* The cell walk's bound with the extinction factor: segment_max_extinction times the largest factor
 * of the cell's corners (refine_majorant sets gCellFactor; both are upper bounds and the float
 * product rounds monotonically, so the product bounds sigma_t(s) x g of every sample). */
float gCellFactor = 1.0;

float segment_majorant(vec3 o, vec3 d, float ta, float tb, ivec3 lo, vec4 c0, vec4 c1)
{
  float m = segment_max_extinction(o, d, ta, tb, lo, c0, c1);
  return VS_SPEC_FACTOR != 0u ? m * gCellFactor : m;
}

/* One step of refine_majorant's bisection in log length, while the bracket is wider than 1%. */
void bisect_step(vec3 o, vec3 d, float t, ivec3 lo, vec4 c0, vec4 c1, inout float hLo, inout float hHi, inout float mLo)
{
  if (!(hHi > 1.01 * hLo))
    return;
  float hMid = sqrt(hLo * hHi);
  float mMid = segment_majorant(o, d, t, t + hMid, lo, c0, c1);
  if (mMid * hMid <= gRefineDepth)
  {
    hLo = hMid;
    mLo = mMid;
  }
  else
    hHi = hMid;
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
  float hMin = vs_walk_min_step(t, gRay.walkScale); /* the brick walk's shortest step (brick_walk.h) */
  vec3 p = o + t * d;
  ivec3 lo = clamp(ivec3(floor(o + (t + 0.5 * hMin) * d)), ivec3(0), max(gDims - 2, ivec3(0)));
  ivec3 hi = min(lo + 1, gDims - 1);
  float e = min(cell_face_distance(p.x, d.x, lo.x, gDims.x),
    min(cell_face_distance(p.y, d.y, lo.y, gDims.y), cell_face_distance(p.z, d.z, lo.z, gDims.z)));
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
  if (VS_SPEC_FACTOR != 0u)
    gCellFactor = vs_cell_max_factor(lo, hi);
  float m = segment_majorant(o, d, t, t + hMax, lo, c0, c1);
  float h = hMax;
  if (m * h > gRefineDepth)
  {
    /* m(h) h grows with h: bisect for the longest h that keeps it below the depth. */
    float hLo = hMin, hHi = hMax;
    float mLo = segment_majorant(o, d, t, t + hLo, lo, c0, c1);
    for (int k = 0; k < 12 && hHi > 1.01 * hLo; ++k)
      bisect_step(o, d, t, lo, c0, c1, hLo, hHi, mLo);
    h = hLo;
    m = mLo;
  }
  tNext = t + h;
  /* The brick majorant bounds the cell too (up to rounding at brick faces). */
  return min(m, mu);
}

/* The majorant segment of the ray from t: returns mu and sets tNext, with mu >= the extinction
 * on [t, tNext). One walk for delta tracking and ratio tracking, without loops. In an empty brick
 * at distance k from the nearest non-empty one, the segment runs to the exit of the cube of
 * (2k - 1)^3 empty bricks around it: one step across empty space instead of one per brick. */
const bool VS_SPEC_SHADOW_CONTROL = (VS_SPEC_CONTROL & VS_CONTROL_SHADOW) != 0u;
const bool VS_SPEC_CAMERA_CONTROL = (VS_SPEC_CONTROL & VS_CONTROL_CAMERA) != 0u;
float gControl; /* majorant_segment's control extinction (VS_SPEC_CONTROL): <= the extinction on the segment */

float majorant_segment(vec3 o, vec3 d, float t, float tEnd, out float tNext)
{
  float tExit;
  ivec3 b = brick_at(o, d, t, tExit);
  vec3 brick = brick_walk_values(b);
  float mu = brick.x;
  if (VS_SPEC_CONTROL != 0u)
    gControl = brick.y;
  if (VS_SPEC_SKIP != 0u && mu == 0.0 && all(greaterThanEqual(b, ivec3(0))) && all(lessThan(b, gBricks)))
  {
    float k = brick.z;
    if (k > 1.0)
      tExit = max(tExit, brick_cube_exit(o, d, t, b, k - 1.0));
  }
  tNext = min(tExit, tEnd);
  if (VS_SPEC_REFINE != 0u && mu * (tNext - t) > gRefineDepth)
    mu = refine_majorant(o, d, t, tNext, mu);
  if (VS_SPEC_CONTROL != 0u)
    gControl = min(gControl, mu);
  return mu;
}

float gQuadOffset; /* P.dims.w: the scalar of code 0 in the quads */

/* The 4 scalars of a quad texel: (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1). */
vec4 quad_scalars(uint q)
{
  return vec4(float(q & 0xffu), float((q >> 8u) & 0xffu), float((q >> 16u) & 0xffu), float(q >> 24u)) + gQuadOffset;
}

/* vs_sample_scalar from the quads: the same corners (integers, exact in float) mixed in the same
 * order, so the same float, from 2 texel reads instead of 8. */
float quad_trilinear(vec3 p)
{
  vec3 q = clamp(p, vec3(0.0), vec3(gDims - 1));
  ivec3 i0 = ivec3(floor(q));
  int z1 = min(i0.z + 1, gDims.z - 1);
  vec3 f = q - vec3(i0);
  vec4 a = quad_scalars(imageLoad(uQuads, i0).r);
  vec4 b = quad_scalars(imageLoad(uQuads, ivec3(i0.xy, z1)).r);
  float c00 = mix(a.x, a.y, f.x);
  float c10 = mix(a.z, a.w, f.x);
  float c01 = mix(b.x, b.y, f.x);
  float c11 = mix(b.z, b.w, f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* The scalar at index-space point p (vs_sample), with the cropping test only in the pipelines that
 * have cropping regions: lavapipe would run it at every step otherwise, whatever the flags. */
float kernel_sample(vec3 p)
{
  if (VS_SPEC_CROPPING != 0u && vs_cropped_out(p))
    return uintBitsToFloat(0x7fc00000u); /* NaN: empty space */
  if (VS_SPEC_INTERPOLATION == VS_INTERPOLATION_NEAREST)
    return vs_sample_nearest(p, gDims);
  return VS_SPEC_QUADS != 0u ? quad_trilinear(p) : vs_sample_scalar(p, gDims);
}

/* The extinction factor at index-space point p (1 without one: the pipelines without gradient
 * opacity read nothing more and compute the same bits, x * 1.0 being x). */
float kernel_factor(vec3 p)
{
  if (VS_SPEC_FACTOR == 0u)
    return 1.0;
  return vs_sample_factor(p, gDims, VS_SPEC_INTERPOLATION);
}

/* The ray interval inside the (cropped) box and the kept side of every clip plane (vs_clip_planes'
 * rule), reading the planes from the parameters in place: passed as an array argument, they were
 * copied into every lane's registers under the lanes' mask at every call (~2,000 instructions per
 * shadow ray on lavapipe, measured in its machine code). */
vec2 ray_interval(vec3 o, vec3 d)
{
  vec2 t = vs_intersect_box(o, d, gBoxMin, gBoxMax);
  for (uint i = 0u; i < gClipCount; ++i)
  {
    vec4 plane = gClipPlanes[i];
    float dn = dot(plane.xyz, d);
    float on = dot(plane.xyz, o) + plane.w;
    if (abs(dn) < 1e-20)
    {
      if (on < 0.0)
        t = vec2(1.0, 0.0);
    }
    else if (dn > 0.0)
      t.x = max(t.x, -on / dn);
    else
      t.y = min(t.y, -on / dn);
  }
  return t;
}

#ifndef VS_NO_GRID
/* The cell one corner of the 8 around index-space point x, picked with its trilinear weight by the
 * pixel's numbers gCellU. */
uvec3 stochastic_cell(vec3 x)
{
  uvec3 cells = gGrid.xyz;
  vec3 c = clamp((x - gBoxMin) / gCellSize - 0.5, vec3(0.0), vec3(cells - 1u));
  uvec3 c0 = uvec3(floor(c));
  uvec3 c1 = min(c0 + 1u, cells - 1u);
  vec3 f = c - vec3(c0);
  vec3 u = gCellU;
  return uvec3(u.x < f.x ? c1.x : c0.x, u.y < f.y ? c1.y : c0.y, u.z < f.z ? c1.z : c0.z);
}

/* The D x D values the strategy warps at index-space point x (direction_map.glsl), with their sum
 * pyramid: one cell's map (stochastic cell), or the maps of the 8 cells around x interpolated. */
void direction_values(vec3 x, uint strategy, uint D, inout VsRng rng)
{
  uvec3 cells = gGrid.xyz;
  vec3 c = (x - gBoxMin) / gCellSize - 0.5;
  c = clamp(c, vec3(0.0), vec3(cells - 1u));
  uvec3 c0 = uvec3(floor(c));
  uvec3 c1 = min(c0 + 1u, cells - 1u);
  vec3 f = c - vec3(c0);
  uint DD = D * D;
  float epsilon = gEpsilon;
  if (VS_SPEC_CELL_MODE == VS_CELL_STOCHASTIC)
  {
    cell_map(stochastic_cell(x), strategy, D, epsilon);
  }
  else
  {
    for (uint n = 0u; n < DD; ++n)
      gValues[n] = 0.0;
    for (uint k = 0u; k < 8u; ++k)
    {
      uvec3 cell = uvec3((k & 1u) != 0u ? c1.x : c0.x, (k & 2u) != 0u ? c1.y : c0.y, (k & 4u) != 0u ? c1.z : c0.z);
      float w = ((k & 1u) != 0u ? f.x : 1.0 - f.x) * ((k & 2u) != 0u ? f.y : 1.0 - f.y) *
        ((k & 4u) != 0u ? f.z : 1.0 - f.z);
      if (w > 0.0)
        for (uint n = 0u; n < DD; ++n)
          gValues[n] += w * visibility_texel(cell, n, D);
    }
    for (uint n = 0u; n < DD; ++n)
      gValues[n] = map_entry(gValues[n], n, strategy, D, epsilon);
  }
  map_pyramid(D);
}

#endif
/* The direction map at x for the grid strategies (once per scatter point, for all its shadow rays):
 * the stochastic cell's table, or the map built here. */
void prepare_directions(vec3 x, uint strategy, inout VsRng rng)
{
  uint D = gGrid.w;
  if (strategy == VS_STRATEGY_ENVIRONMENT || strategy == VS_STRATEGY_UNIFORM || D == 0u)
    return;
#ifndef VS_NO_GRID
  if (VS_SPEC_TABLE != 0u)
  {
    uvec3 cell = stochastic_cell(x);
    gTableBase = 2u * vs_table_nodes(D) * ((cell.z * gGrid.y + cell.y) * gGrid.x + cell.x);
  }
  else
    direction_values(x, strategy, D, rng);
#endif
}

/* A direction from the strategy (after prepare_directions at the scatter point) and its pdf. */
vec3 sample_direction(uint strategy, vec2 u, out float pdf)
{
  uint K = gEnvLevels;
  uint D = gGrid.w;
  if (strategy == VS_STRATEGY_ENVIRONMENT)
    return vs_sample_environment(K, u, pdf);
  if (strategy == VS_STRATEGY_UNIFORM || D == 0u)
    return vs_sample_uniform(u, pdf);
#ifdef VS_NO_GRID
  return vs_sample_uniform(u, pdf); /* not reached: MonteCarloPass uses this module for the other two only */
#else
  if (VS_SPEC_DEFENSIVE != 0u && strategy == VS_STRATEGY_TWO_STEP)
  {
    float alpha = gMixture;
    if (VS_SPEC_TABLE != 0u)
      return vs_sample_defensive_table(gTableBase, D, K, alpha, u, pdf);
    return vs_sample_defensive_pyramid(D, K, alpha, u, pdf);
  }
  if (VS_SPEC_TABLE != 0u)
    return vs_sample_direction_table(strategy, gTableBase, D, K, u, pdf);
  return vs_sample_direction_pyramid(strategy, D, K, u, pdf);
#endif
}

/* ------------------------------------------------------------------ tracking */


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
        float si = dot(ws, vec3(0.2126, 0.7152, 0.0722));
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

/* One path of pixel `pix`: sample `sampleIndex` of the image (its random numbers depend on the
 * pixel, the sample index and the seed only). Returns (rgb, alpha); adds the back-edges of its
 * camera and shadow rays to cameraCost and shadowCost, and says whether it scattered. */
vec4 render_sample(uvec2 pix, uint sampleIndex, float depth, uint scatterCostPerRay, inout uint cameraCost,
  inout uint shadowCost, out bool scattered)
{
  scattered = false;
  uint W = gViewport.x, H = gViewport.y;
  VsRng rng = vs_rng_init(pix, sampleIndex, gViewport.w);
  /* Under the Sobol sampler (VS_SAMPLER_SOBOL) the pixel jitter, the light directions and the first
   * two steps of each shadow ray's tracking come from the pixel's own scrambled Sobol sequences
   * (sobol.h; three seeds, so the three are independent), indexed by the sample: unbiased, and
   * stratified across the pixel's samples; everything else from the sample's hash stream. */
  uvec3 sobolSeeds = VS_SPEC_SOBOL ? vs_pcg4d(uvec4(pix, gViewport.w, 0x50b01u)).xyz : uvec3(0u);
  vec2 jitter = VS_SPEC_SOBOL ? vs_sobol_2d(sampleIndex, sobolSeeds.x) : vs_rng_vec2(rng);
  vec2 ndc = (vec2(pix) + jitter) / vec2(W, H) * 2.0 - 1.0;
  vec4 pn = gInvViewProj * vec4(ndc, -1.0, 1.0);
  vec4 pf = gInvViewProj * vec4(ndc, 1.0, 1.0);
  vec3 ow = pn.xyz / pn.w;
  vec3 dw = normalize(pf.xyz / pf.w - ow);
  float tDepth = 1e30;
  if (depth < 1.0)
  {
    vec4 pd = gInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    tDepth = dot(pd.xyz / pd.w - ow, dw);
  }
  vec3 o = (gWorldToIndex * vec4(ow, 1.0)).xyz;
  vec3 d = (gWorldToIndex * vec4(dw, 0.0)).xyz;
  vec2 ti = ray_interval(o, d);
  float t0 = max(ti.x, 0.0), t1 = min(ti.y, tDepth);

  vec4 result = vec4(0.0);
  bool seesEnvironment = tDepth >= 1e30 && gBackgroundVisible;
  /* The scatter point, and the factor its in-scattered light is scored with (albedo for delta
   * tracking's collision; the reservoir's weight otherwise). */
  bool scatter = false;
  float tHit = 0.0;
  vec3 albedo = vec3(0.0);
  if (VS_SPEC_CAMERA == VS_CAMERA_RESERVOIR)
  {
    float T = 1.0;
    if (t0 < t1)
      camera_reservoir(o, d, t0, t1, rng, VS_TRACKING_CAP, cameraCost, tHit, albedo, T);
    scatter = tHit >= 0.0 && t0 < t1 && any(greaterThan(albedo, vec3(0.0)));
    result = seesEnvironment ? vec4(T * env_radiance_display(dw), gEscapeAlpha > 0.5 ? 1.0 : 1.0 - T)
                             : vec4(0.0, 0.0, 0.0, 1.0 - T);
  }
  else if (t0 < t1 && delta_track(o, d, t0, t1, rng, VS_TRACKING_CAP, cameraCost, tHit, albedo))
  {
    result.a = 1.0;
    scatter = any(greaterThan(albedo, vec3(0.0)));
  }
  else if (seesEnvironment)
  {
    result = vec4(env_radiance_display(dw), gEscapeAlpha);
  }
  if (scatter)
  {
    scattered = true;
    vec3 x = o + tHit * d;
    prepare_directions(x, gStrategy, rng);
    /* gShadowRays directions per scatter point (splitting): their mean is an unbiased estimate
     * of the in-scattered light at x, for the cost of one camera ray. */
    vec3 sum = vec3(0.0);
    uint shadowLeft = gShadowBudget; /* the same in every lane here: it drops by the group's steps */
    for (uint k = 0u; k < gShadowRays; ++k)
    {
      float pdf;
      /* The light's 2D number: the pixel's Sobol point (its samples' directions stratified), or the
       * sample's own random pair. */
      vec2 u = VS_SPEC_SOBOL ? vs_sobol_2d(sampleIndex * gShadowRays + k, sobolSeeds.y) : vs_rng_vec2(rng);
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
        vec2 strata = VS_SPEC_SOBOL ? vs_sobol_2d(sampleIndex * gShadowRays + k, sobolSeeds.z) : vec2(-1.0);
        float T = shadow_transmittance(x, di, 0.0, ts.y, strata, rng, min(VS_TRACKING_CAP, max(shadowLeft, 1u)), steps);
        sum += T * Le / pdf;
      }
      /* The lanes here run each shadow ray's loop as long as the longest of them. */
      uint groupSteps = subgroupMax(steps);
      shadowLeft -= min(shadowLeft, groupSteps);
      shadowCost += groupSteps + scatterCostPerRay;
    }
    result.rgb += albedo * VS_INV_4PI * sum / float(gShadowRays);
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
  bool inside = pix.x < W && pix.y < H;
  gEnvScale = P.sampling2.y;
  gEpsilon = P.sampling2.x;
  gSquareScale = P.sampling2.w;
  gMixture = P.mixture.x;
  gEnvLevels = P.sampling.w;
  gBoxMin = P.boxMin.xyz;
  gBoxMax = P.boxMax.xyz;
  gCellSize = P.cellSize.xyz;
  gGrid = P.grid;
  gViewport = P.viewport;
  gBackgroundVisible = P.background.w > 0.5;
  gEscapeAlpha = P.background.w > 1.5 ? 0.0 : 1.0;
  gWorldToIndex = P.worldToIndex;
  gInvViewProj = P.invViewProj;
  /* Unrolled (the kernel's loops count against lavapipe's loop limiter, see the top): as many as
   * VS_MAX_CLIP_PLANES (gClipPlanes' size would not compile otherwise). */
  gClipPlanes[0] = P.clipPlanes[0];
  gClipPlanes[1] = P.clipPlanes[1];
  gClipPlanes[2] = P.clipPlanes[2];
  gClipPlanes[3] = P.clipPlanes[3];
  gClipPlanes[4] = P.clipPlanes[4];
  gClipPlanes[5] = P.clipPlanes[5];
  gClipPlanes[6] = P.clipPlanes[6];
  gClipPlanes[7] = P.clipPlanes[7];
  gDims = ivec3(P.dims.xyz);
  gQuadOffset = P.dims.w;
  gBricks = ivec3(P.bricks.xyz);
  gBrickSize = P.sampling2.z;
  gInvBrickSize = 1.0 / P.sampling2.z;
  gTF = P.tf;
  gEnvSize = 1u << P.sampling.w;
  gClipCount = P.bricks.w;
  gStrategy = VS_SPEC_STRATEGY;
  gShadowRays = clamp(uint(P.tracking.y), 1u, 64u);
  gRefineDepth = P.tracking.x > 0.0 ? P.tracking.x : 32.0;
  gInterpolation = VS_SPEC_INTERPOLATION;
  vs_set_cropping(P.cropLo, P.cropHi, VS_SPEC_CROPPING != 0u ? P.crop.x : 0u);
#ifndef VS_NO_GRID
  uvec4 cellHash = vs_pcg4d(uvec4(pix, gViewport.w, 0xce11u));
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
  uint scatterCost = scatter_cost(gStrategy, P.grid.w, P.sampling.w, VS_SPEC_CELL_MODE);
  /* Per shadow ray: its direction (the map is made once: counted in the first) and its clip planes. */
  uint perRay = 16u + 2u * P.sampling.w + 6u + 4u;
  /* The shadow rays of a sample share the steps the budget leaves after the rest of its worst
   * case, each ray at most VS_TRACKING_CAP: up to 6 rays keep that cap each (the budget holds them),
   * more share it so that one sample always fits (64 rays: ~800 steps each if all need them; a ray
   * that reaches its cap scores transmittance 0, as at VS_TRACKING_CAP). */
  uint sampleFixed = VS_TRACKING_CAP + 1u + scatterCost + gShadowRays * (1u + perRay) + VS_START_COST + VS_SAMPLE_SLACK;
  gShadowBudget = min(gShadowRays * VS_TRACKING_CAP, VS_LOOP_BUDGET - min(sampleFixed + gShadowRays, VS_LOOP_BUDGET));
  uint sampleMax = sampleFixed + gShadowBudget;
  uint cost = 0u;
  while (subgroupAny(done < pc.target) && cost + sampleMax <= VS_LOOP_BUDGET)
  {
    uint cameraCost = 0u, shadowCost = 0u;
    bool scattered = false;
    if (done < pc.target)
    {
      accumulate(acc, render_sample(pix, done, depth, perRay, cameraCost, shadowCost, scattered));
      done += 1u;
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
    if (done < pc.target)
      atomicAdd(uCount[W * H], 1u);
  }
#ifdef VS_COUNT_LOOKUPS
  atomicAdd(uLookups[0], gLookups.x);
  atomicAdd(uLookups[1], gLookups.y);
  atomicAdd(uLookups[2], gLookups.z);
  atomicAdd(uLookups[3], gLaneSteps);
  atomicAdd(uLookups[4], gGroupLaneSteps);
#endif
}
