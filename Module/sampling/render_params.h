/*
 * render_params.h — what a Monte Carlo render dispatch needs (std430; vec4/uvec4/mat4
 * members only), shared by mc_render.glsl and the host.
 *
 * Marching happens in index space (voxel centres at integers) with the ray
 * parameter t in world units: o_i = worldToIndex o, d_i = worldToIndex_linear d for a
 * unit world direction d, so extinction (per world unit) integrates over t directly.
 */
#ifndef VS_RENDER_PARAMS_H
#define VS_RENDER_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

VS_CONST uint VS_CELL_TRILINEAR = 0u;  /* interpolate the 8 cells' maps (von Radziewsky et al. 2017) */
VS_CONST uint VS_CELL_STOCHASTIC = 1u; /* pick one cell with its trilinear weight */

VS_CONST uint VS_CAMERA_COLLISION = 0u; /* the camera ray delta-tracked to one real collision */
VS_CONST uint VS_CAMERA_RESERVOIR = 1u; /* ratio-tracked, one scatter point resampled from all its
                                          tentative collisions (mc_render.glsl camera_reservoir) */

/* Control extinctions (the majorant grid's per-brick lower bound, MajorantGrid::ControlImage), bits:
 * the shadow rays by residual ratio tracking (Novak et al. 2014), the camera ray by decomposition
 * tracking (Kutz et al. 2017). 0: plain ratio and delta tracking. */
VS_CONST uint VS_CONTROL_SHADOW = 1u;
VS_CONST uint VS_CONTROL_CAMERA = 2u;

/* The shadow rays' transmittance estimator: ratio tracking (residual ratio tracking with
 * VS_CONTROL_SHADOW), or Kettunen et al. 2021's unbiased ray marching (ray_marching.h; the march
 * integrates the control exactly with VS_CONTROL_SHADOW). */
VS_CONST uint VS_TRANSMITTANCE_RATIO_TRACKING = 0u;
VS_CONST uint VS_TRANSMITTANCE_RAY_MARCHING = 1u;

/* Where a sample's pixel jitter and light direction numbers come from: the sample's own hash
 * stream (independent samples), or the pixel's Owen-scrambled Sobol sequences (sobol.h). */
VS_CONST uint VS_SAMPLER_INDEPENDENT = 0u;
VS_CONST uint VS_SAMPLER_SOBOL = 1u;

/* Loop back-edges one invocation of the render kernel takes at most per dispatch (an upper bound
 * the kernel keeps). Lavapipe ends every loop of an invocation once they have taken 65535 together
 * (llvmpipe's loop limiter), silently: the kernel stops below that and resumes in the next dispatch
 * (TestDriverLoopLimit). */
VS_CONST uint VS_LOOP_BUDGET = 60000u;

/* The grid directions the render kernel reads at most: D x D for D <= 16 (direction_map.glsl). */
VS_CONST uint VS_MAX_RENDER_DIRECTIONS = 256u;

struct VsRenderParams
{
  mat4 invViewProj;  /* OpenGL NDC (z in [-1,1]) -> world */
  mat4 worldToIndex;
  vec4 boxMin;       /* index-space box of the volume (cropped) */
  vec4 boxMax;
  vec4 dims;         /* xyz: voxels per axis; w: the scalar of code 0 in the volume's 8-bit quads
                        (vsDeviceVolume.h, the render kernel's VS_SPEC_QUADS pipelines) */
  vec4 tf;           /* transfer-function LUT parameters (frame_params.h) */
  vec4 background;   /* rgb: constant background; w: 1 = escaping rays see the environment (alpha 1),
                        2 = they see it with alpha 0 (the radiance as with 1, the alpha the volume's
                        coverage), 0 = transparent */
  uvec4 viewport;    /* width, height, index of the first sample of this frame, seed */
  uvec4 sampling;    /* x: strategy, y: samples per pixel this frame, z: cell mode, w: env finest level K */
  vec4 sampling2;    /* x: epsilon added to visibility, y: environment intensity, z: majorant brick size,
                        w: scale of the radiance in the sum of squares (0 = 1), see mc_render.glsl */
  uvec4 grid;        /* visibility cells (xyz), w: directions per side D (0 = no grid) */
  vec4 cellSize;     /* index units per visibility cell */
  uvec4 bricks;      /* majorant bricks (xyz), w: clip planes in use */
  vec4 clipPlanes[VS_MAX_CLIP_PLANES];/* index space: kept where dot(n, x) + w >= 0 */
  vec4 tracking;     /* x: optical depth of a majorant segment above which the trackers walk voxel
                        cells instead of the brick (0 = 32), see mc_render.glsl; y: shadow rays per
                        scatter point (0 = 1, at most 64); z: the camera estimator (VS_CAMERA_*);
                        w: the scalar's interpolation (interpolation.h: 0 linear, 1 nearest) */
  vec4 cropLo;       /* the cropping regions (vsVolumeGeometry.h): index-space planes, xyz */
  vec4 cropHi;
  uvec4 crop;        /* x: the regions' flags (0 = none: the box is all); y: VS_CONTROL_* bits (ignored with
                        cropping regions: hidden regions have no extinction); z: the sampler (VS_SAMPLER_*);
                        w: 1 = the extinction is scaled by the volume's factor (the gradient opacity;
                        MonteCarloPass sets it from the DeviceVolume) */
  vec4 mixture;      /* x: TwoStep's defensive weight alpha, the probability of an Environment sample
                        (strategies.h vs_sample_defensive_*; 0 = plain TwoStep); y: the shadow rays'
                        transmittance estimator (VS_TRANSMITTANCE_*); z, w: unused */
  uvec4 directionSources[VS_MAX_RENDER_DIRECTIONS / 4u]; /* entry n (component n % 4 of element n / 4): the
                        grid direction whose values direction n reads (VisibilityGrid::DirectionSources;
                        direction_map.glsl); MonteCarloPass sets it from the grid */
};

VS_NAMESPACE_END

#endif
