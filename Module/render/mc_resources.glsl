/*
 * mc_resources.glsl — what the render kernel (mc_render.glsl) binds and keeps in registers: its
 * specialization constants, descriptor bindings, the parameters loaded once per invocation, the
 * ray being tracked, and the environment's radiance lookups. Included once, by mc_render.glsl.
 */

#include "bindings.h"
#include "kernel_spec.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

/* Specialization constants: the host compiles one pipeline per combination it renders with, so the
 * code of the other strategies, the other cell mode and (where no brick is optically thick) the
 * cell walk is gone. That matters on lavapipe, which runs both sides of every `if` (masked) and
 * every loop body at least once: such code costs as if it were always taken. */
layout(constant_id = VS_SPEC_ID_STRATEGY) const uint VS_SPEC_STRATEGY = 4u;  /* VS_STRATEGY_*, = P.strategy */
layout(constant_id = VS_SPEC_ID_CELL_MODE) const uint VS_SPEC_CELL_MODE = 1u; /* VS_CELL_*, = P.cellMode */
layout(constant_id = VS_SPEC_ID_REFINE) const uint VS_SPEC_REFINE = 1u;    /* 0: no majorant segment reaches the refinement depth */
layout(constant_id = VS_SPEC_ID_CAMERA) const uint VS_SPEC_CAMERA = 0u;    /* VS_CAMERA_*, = P.cameraEstimator */
layout(constant_id = VS_SPEC_ID_INTERPOLATION) const uint VS_SPEC_INTERPOLATION = 0u; /* interpolation.h, = P.volume.interpolation */
layout(constant_id = VS_SPEC_ID_CROPPING) const uint VS_SPEC_CROPPING = 0u;  /* 1: cropping regions (P.volume.cropFlags != 0) */
layout(constant_id = VS_SPEC_ID_DEFENSIVE) const uint VS_SPEC_DEFENSIVE = 0u; /* 1: TwoStep mixed with Environment sampling (P.defensiveWeight) */
layout(constant_id = VS_SPEC_ID_SKIP) const uint VS_SPEC_SKIP = 1u;      /* 1: empty space is crossed in one step (VS_MC_BRICKS' distance) */
layout(constant_id = VS_SPEC_ID_QUADS) const uint VS_SPEC_QUADS = 0u;     /* 1: trilinear samples read the volume's 8-bit quads
                                                             (binding 15, vsDeviceVolume.h) */
layout(constant_id = VS_SPEC_ID_SAMPLER) const uint VS_SPEC_SAMPLER = 0u;   /* VS_SAMPLER_* (mc_params.h), = P.pixelSampler */
const bool VS_SPEC_SOBOL = VS_SPEC_SAMPLER == VS_SAMPLER_SOBOL;
layout(constant_id = VS_SPEC_ID_CONTROL) const uint VS_SPEC_CONTROL = 0u;   /* VS_CONTROL_* bits (mc_params.h): the trackers
                                                              split the extinction into the brick's control (uBricks.y) and the rest */
layout(constant_id = VS_SPEC_ID_TRANSMITTANCE) const uint VS_SPEC_TRANSMITTANCE = 0u; /* VS_TRANSMITTANCE_* (mc_params.h): the shadow
                                                              rays' estimator, = P.transmittance */
layout(constant_id = VS_SPEC_ID_FACTOR) const uint VS_SPEC_FACTOR = 0u;   /* 1: the extinction is scaled by the volume's factor
                                                              (the gradient opacity, binding 16; = P.volume.extinctionFactor) */
layout(constant_id = VS_SPEC_ID_PATH) const uint VS_SPEC_PATH = 0u;    /* 0: single scattering with the isotropic phase
                                                             (render_sample); 1: full transport, a path per
                                                             sample (mc_path.glsl), any event limit and phase */
layout(constant_id = VS_SPEC_ID_LOOP_BUDGET) const uint VS_SPEC_LOOP_BUDGET = VS_LOOP_BUDGET; /* the sample loop's budget of back-edges:
                                                             VS_LOOP_BUDGET where the driver has a loop limiter (lavapipe), else
                                                             none (1 << 30; vs::DeviceInfo::LoopLimited, vsMonteCarloPass) */
layout(constant_id = VS_SPEC_ID_SURFACE) const uint VS_SPEC_SURFACE = 0u;  /* 1: hybrid scattering, a surface lobe where the gradient
                                                             is strong (surface_scattering.glsl; = P.surface with a
                                                             blending below 2); full transport only */
layout(constant_id = VS_SPEC_ID_LIGHTS) const uint VS_SPEC_LIGHTS = 0u;   /* 1: VTK's lights beside the environment (scene_lights.glsl;
                                                             P.lightCount > 0); full transport only */
layout(constant_id = VS_SPEC_ID_TABLE) const uint VS_SPEC_TABLE = 0u;     /* 1: the grid strategies read the cell's direction
                                                             table (binding 12), stochastic cell only */
layout(binding = VS_MC_VOLUME, r32f) uniform readonly image3D uVolume;
#define VS_TF_TEXELS
layout(binding = VS_MC_TF) uniform samplerBuffer uTF;
layout(binding = VS_MC_BRICKS, rgba32f) uniform readonly image3D uBricks; /* per brick: majorant, control, empty distance, 0
                                                                  (vsMajorantGrid.h TrackingImage) */
layout(binding = VS_MC_VISIBILITY, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = VS_MC_PARAMS) readonly buffer Params { VsMonteCarloParams P; };
/* Tables read at per-lane indices are texel buffers: lavapipe loads them with vector gathers, and
 * a storage buffer with a scalar loop over the SIMD lanes (measured: ~15% of the kernel's time). */
layout(binding = VS_MC_ENV) uniform samplerBuffer uEnv;  /* rgba32f: the environment's radiance per texel */
layout(binding = VS_MC_MIPS) uniform samplerBuffer uMips; /* r32f: its luminance mip pyramid */
layout(std430, binding = VS_MC_DEPTH) readonly buffer Depth { float uDepth[]; };
layout(std430, binding = VS_MC_SUM) buffer Sum { vec4 uSum[]; };
layout(std430, binding = VS_MC_COMPENSATION) buffer Compensation { vec4 uComp[]; };
layout(std430, binding = VS_MC_SQUARES) buffer Squares { vec4 uSq[]; };
/* Samples each pixel holds (W x H), then one counter of the pixels a dispatch left short of target,
 * then one of the scattering events a Render's paths reached (full transport). */
layout(std430, binding = VS_MC_PROGRESS) buffer Progress { uint uCount[]; };
/* The direction table (sampling/direction_table.h): per cell, the shares of its map's quadtree nodes. */
layout(binding = VS_MC_TABLE) uniform usamplerBuffer uTable; /* r32ui */
/* An integer-coded volume's quads: texel (x, y, z) packs the 8-bit codes of voxels (x, y), (x + 1, y),
 * (x, y + 1), (x + 1, y + 1) of slice z; the scalar is code + P.volume.quadZero. */
layout(binding = VS_MC_QUADS, r32ui) uniform readonly uimage3D uQuads;
/* The extinction factor per voxel (vsDeviceVolume.h; read only with VS_SPEC_FACTOR). */
layout(binding = VS_MC_FACTOR_IMAGE, r32f) uniform readonly image3D uFactor;
#define VS_FACTOR_IMAGE
layout(push_constant) uniform Push { uint target; } pc;

/* The instrumented variant (mc_render_count.comp) counts what a sample reads:
 * uLookups[0] trilinear volume samples, [1] majorant-brick loads, [2] visibility texels (or table nodes),
 * and how busy the SIMD lanes are: [3] the tracking steps the lanes took, [4] the steps their
 * subgroups ran times the subgroup's size. */
#ifdef VS_COUNT_LOOKUPS
layout(std430, binding = VS_MC_LOOKUPS) buffer Lookups { uint uLookups[]; };
uvec3 gLookups = uvec3(0u);
uint gShadowRaysCast = 0u, gShadowRaysBlocked = 0u; /* shadow rays traced, and those with T < 0.01 */
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

/* The surface lobe's gradient reads the scalar as the trackers do (from the quads when the pipeline
 * has them: the float image is then not bound, vsMonteCarloPass.cxx); kernel_volume.glsl defines it. */
float kernel_sample(vec3 p);
#define VS_GRADIENT_SAMPLE(p) kernel_sample(p)
#include "volume_access.glsl"
#ifndef VS_NO_GRID
#include "direction_map.glsl"
#endif
#include "environment_display.glsl"

/* Parameters the per-sample code reads, loaded once per invocation in main(): lavapipe loads a
 * storage-buffer value inside code that not every lane runs with a scalar loop over the lanes
 * (one masked load per lane), even at a uniform address (measured in its machine code). */
float gEnvScale;    /* P.environmentIntensity */
float gEpsilon;     /* P.visibilityEpsilon */
float gSquareScale; /* P.squareScale */
float gMixture;     /* P.defensiveWeight */
uint gEnvLevels;    /* P.environmentLevels */
vec3 gBoxMin, gBoxMax, gCellSize;
uvec3 gGridCells; /* P.grid */
uint gGridSide;
uint gWidth;       /* P.camera */
uint gHeight;
uint gSeed;
bool gBackgroundVisible;
/* The alpha of a camera ray that escapes to the environment: 1 (P.background = VS_BACKGROUND_ENVIRONMENT, the image is
 * opaque) or 0 (VS_BACKGROUND_ENVIRONMENT_COVERAGE: the radiance still includes the environment seen through the volume, but the
 * alpha is the volume's coverage, so the host can composite it over a background it draws itself). */
float gEscapeAlpha;
mat4 gWorldToIndex, gInvViewProj;
vec4 gClipPlanes[VS_MAX_CLIP_PLANES == 8u ? 8 : -1]; /* main() copies 8 */

/* Registers, loaded once per invocation (lavapipe does not hoist buffer loads). */
ivec3 gDims;
ivec3 gBricks;
float gBrickSize;
VsTransferFunction gTF;
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
/* Full transport (VS_SPEC_PATH): the event limit, the phase's g, Russian roulette's first event, VS_MIS_*. */
uint gMaxEvents;
float gAnisotropy;
uint gRouletteDepth;
uint gMis;
uint gLightLo, gLightHi; /* P.lightEvents: next-event estimation at events gLightLo ..= gLightHi */
uint gShadowBudget; /* tracking steps the shadow rays of one sample share (main) */
uint gShadowLeft;   /* issue 38: what an event's environment shadow rays left of it (light_samples), for VTK's lights */
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
uint gInterpolation; /* interpolation.h: the scalar's reconstruction (P.volume.interpolation) */
vec3 env_radiance(vec3 w)
{
  uvec2 t = vs_dir_to_texel(w, gEnvSize);
  return texelFetch(uEnv, int(t.y * gEnvSize + t.x)).rgb * gEnvScale;
}

/* The environment seen directly (the background; environment_display.glsl). */
vec3 env_radiance_display(vec3 w)
{
  return vs_environment_bilinear(uEnv, gEnvSize, w) * gEnvScale;
}
