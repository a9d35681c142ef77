/*
 * mc_params.h — what a Monte Carlo render dispatch needs (std430, the layout rule of
 * volume_params.h), shared by mc_render.glsl and the host: the camera, the volume and the grid
 * as every pass sees them, and the estimator's own settings.
 */
#ifndef VS_MC_PARAMS_H
#define VS_MC_PARAMS_H
#include "camera_params.h"
#include "grid_params.h"
#include "scene_lights.h"
#include "volume_params.h"

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

/* How the environment seen at a scattering event is estimated under full transport (mc_path.glsl):
 * both next-event estimation with the strategy's direction and the phase-sampled continuation, weighted
 * by the power heuristic (mis.h); or one of them alone (both unbiased; for tests and measurements). */
VS_CONST uint VS_MIS_POWER = 0u;      /* light sampling and phase sampling, power heuristic */
VS_CONST uint VS_MIS_LIGHT_ONLY = 1u; /* next-event estimation alone: an escaping continuation adds nothing */
VS_CONST uint VS_MIS_PHASE_ONLY = 2u; /* the continuation alone: no shadow rays at the events */
VS_CONST uint VS_MIS_BALANCE = 3u;    /* both, balance heuristic */

/* Scattering events a path may have at most (maxEvents), and the default: high enough that truncation
 * loses far below 0.5% of the energy on the benchmark scenes (docs/benchmarks.md); Russian roulette ends
 * paths long before it. */
VS_CONST uint VS_MAX_SCATTERING_EVENTS = 100000u;
VS_CONST uint VS_DEFAULT_SCATTERING_EVENTS = 1024u;
/* The event from which Russian roulette may end a path (rouletteDepth 0 = this). */
VS_CONST uint VS_DEFAULT_ROULETTE_DEPTH = 4u;

/* Loop back-edges one invocation of the render kernel takes at most per dispatch (an upper bound
 * the kernel keeps). Lavapipe ends every loop of an invocation once they have taken 65535 together
 * (llvmpipe's loop limiter), silently: the kernel stops below that and resumes in the next dispatch
 * (TestDriverLoopLimit). */
VS_CONST uint VS_LOOP_BUDGET = 60000u;

/* The grid directions the render kernel reads at most: D x D for D <= 16 (direction_map.glsl). */
VS_CONST uint VS_MAX_RENDER_DIRECTIONS = 256u;

/* What escaping camera rays show (VsMonteCarloParams::background). */
VS_CONST uint VS_BACKGROUND_TRANSPARENT = 0u;          /* nothing: alpha 0, VTK's background shows */
VS_CONST uint VS_BACKGROUND_ENVIRONMENT = 1u;          /* the environment, alpha 1 (an opaque image) */
VS_CONST uint VS_BACKGROUND_ENVIRONMENT_COVERAGE = 2u; /* the environment in the radiance, the alpha the
                                                          volume's coverage (composited over a skybox) */

struct VsMonteCarloParams
{
  VsCameraParams camera;  /* camera.frame: the index of this frame's first sample per pixel */
  VsVolumeParams volume;  /* volume.quadZero and volume.extinctionFactor: MonteCarloPass sets them
                             from the DeviceVolume */
  VsGridParams grid;      /* grid.side 0: no grid */
  /* How the light direction of a scatter point is sampled (strategies.h). */
  uint strategy;          /* VS_STRATEGY_* */
  uint samplesPerFrame;   /* samples per pixel this frame */
  uint cellMode;          /* how a point reads the grid's cells: VS_CELL_* */
  uint environmentLevels; /* the environment pyramid's finest level K (2^K x 2^K importance texels) */
  float visibilityEpsilon;    /* added to the visibility in TwoStep's product pdf (never 0 where light is) */
  float environmentIntensity; /* the environment's radiance scale */
  float squareScale;      /* scale of the radiance in the sums of squares (0 = 1), see mc_render.glsl */
  float defensiveWeight;  /* TwoStep's defensive weight alpha, the probability of an Environment sample
                             (strategies.h vs_sample_defensive_*; 0 = plain TwoStep) */
  /* The trackers. */
  float cellWalkDepth;    /* optical depth of a majorant segment above which the trackers walk voxel
                             cells instead of the brick (0 = 32), see mc_render.glsl */
  uint shadowRays;        /* shadow rays per scatter point (0 = 1, at most 64) */
  uint cameraEstimator;   /* VS_CAMERA_* */
  uint transmittance;     /* the shadow rays' transmittance estimator: VS_TRANSMITTANCE_* */
  uint background;        /* what escaping camera rays show: VS_BACKGROUND_* */
  uint controlExtinction; /* VS_CONTROL_* bits (ignored with cropping regions: hidden regions have no
                             extinction) */
  uint pixelSampler;       /* VS_SAMPLER_* */
  /* Full transport (mc_path.glsl). maxEvents 1 with anisotropy 0 is single scattering with the
   * isotropic phase, rendered by the single-scattering estimator (mc_render.glsl render_sample). */
  uint maxEvents;         /* scattering events per path, 1 .. VS_MAX_SCATTERING_EVENTS (0 = 1) */
  float anisotropy;       /* the Henyey-Greenstein phase function's g, in (-1, 1) */
  uint rouletteDepth;     /* events before Russian roulette may end a path (0 = VS_DEFAULT_ROULETTE_DEPTH) */
  uint mis;               /* VS_MIS_* */
  /* Benchmarks: next-event estimation only at events lo ..= hi (bits 0-15 lo, 16-31 hi; 0: at
   * every event). With VS_MIS_LIGHT_ONLY the image is then the light that reaches the camera
   * through those events alone (vissweep bench events). */
  uint lightEvents;
  uvec4 directionSources[VS_MAX_RENDER_DIRECTIONS / 4u]; /* entry n (component n % 4 of element n / 4): the
                        grid direction whose values direction n reads (VisibilityGrid::DirectionSources;
                        direction_map.glsl); MonteCarloPass sets it from the grid */
  /* ---- issue 38: hybrid scattering (surface_scattering.glsl, microfacet.h). Added at the end. ---- */
  uint surface;            /* 1: a scattering event may scatter off the gradient's surface (the property's
                              ShadeOn; the kernel's VS_SPEC_SURFACE); 0: the phase function alone */
  float surfaceBlending;   /* VTK 9.2's VolumetricScatteringBlending in [0, 2] (vs_surface_probability):
                              0 a surface wherever the gradient allows, 2 volumetric only */
  float surfaceDiffuse;    /* the lobe's diffuse weight (times the albedo) and specular weight, kd + ks <= 1 */
  float surfaceSpecular;   /*   (vs_surface_weights of the property's Diffuse and Specular) */
  float surfaceRoughness;  /* GGX alpha (vs_roughness_from_specular_power of SpecularPower) */
  float gradientScale;     /* |grad s|_n = min(1, |grad s| gradientScale), |grad s| per world unit: the mean
                              voxel spacing / (0.25 x the data's scalar range), vtkGPUVolumeRayCastMapper's */
  float opacityDistance;   /* the opacity at the event is 1 - exp(-sigma_t opacityDistance): the unit distance
                              over the density scale, so that it is the transfer function's alpha */
  uint surfacePad;
  /* ---- issue 38: VTK's lights (scene_lights.h, scene_lights.glsl), beside the environment. ---- */
  uint lightCount;         /* lights[0 .. lightCount) are lit by next-event estimation at every event (the
                              kernel's VS_SPEC_LIGHTS); 0: the environment alone */
  uint lightPad0, lightPad1, lightPad2;
  VsSceneLight lights[VS_MAX_SCENE_LIGHTS];
};

VS_NAMESPACE_END

#endif
