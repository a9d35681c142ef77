/*
 * bindings.h — the descriptor binding numbers of every compute shader, named once for both sides:
 * the GLSL declares `layout(binding = VS_MC_VOLUME, ...)`, the host binds `set.Bind(VS_MC_VOLUME,
 * ...)` and lists the binding's type at the same name (vs::BindingTypes, vsPipeline.h). A shader's
 * bindings are numbered from 0 without gaps (one descriptor set per pass), except where a variant
 * leaves one unused (said beside it).
 */
#ifndef VS_BINDINGS_H
#define VS_BINDINGS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The Monte Carlo render kernel (render/mc_resources.glsl, render/vsMonteCarloPass.cxx). */
VS_CONST uint VS_MC_VOLUME = 0u;         /* r32f image: the scalar volume */
VS_CONST uint VS_MC_TF = 1u;             /* rgba32f texel buffer: the transfer function's entries */
VS_CONST uint VS_MC_BRICKS = 2u;         /* rgba32f image: majorant, control, empty distance per brick */
VS_CONST uint VS_MC_VISIBILITY = 3u;     /* the visibility grid (its storage format) */
VS_CONST uint VS_MC_PARAMS = 4u;         /* storage buffer: VsMonteCarloParams */
VS_CONST uint VS_MC_ENV = 5u;            /* rgba32f texel buffer: the environment's radiance */
VS_CONST uint VS_MC_MIPS = 6u;           /* r32f texel buffer: its luminance mip pyramid */
VS_CONST uint VS_MC_DEPTH = 7u;          /* storage buffer: the opaque geometry's depth per pixel */
VS_CONST uint VS_MC_SUM = 8u;            /* storage buffers: the accumulators */
VS_CONST uint VS_MC_COMPENSATION = 9u;
VS_CONST uint VS_MC_SQUARES = 10u;
VS_CONST uint VS_MC_PROGRESS = 11u;      /* storage buffer: samples per pixel, then the short count */
VS_CONST uint VS_MC_TABLE = 12u;         /* r32ui texel buffer: the direction table */
VS_CONST uint VS_MC_RETIRED = 13u;       /* declared by no variant (was the empty-space distance, now in
                                            VS_MC_BRICKS): a placeholder, so the numbers after it stay */
VS_CONST uint VS_MC_LOOKUPS = 14u;       /* storage buffer: the counting variant's counters */
VS_CONST uint VS_MC_QUADS = 15u;         /* r32ui image: the 8-bit volume's quads */
VS_CONST uint VS_MC_FACTOR_IMAGE = 16u;        /* r32f image: the extinction factor per voxel */
VS_CONST uint VS_MC_PATH_POSITION = 17u; /* storage buffers: the paths in flight between dispatches */
VS_CONST uint VS_MC_PATH_DIRECTION = 18u; /* (path_state.glsl; unread by the single-scattering estimator) */
VS_CONST uint VS_MC_PATH_THROUGHPUT = 19u;
VS_CONST uint VS_MC_PATH_RADIANCE = 20u;
VS_CONST uint VS_MC_BINDING_COUNT = 21u;

/* The emission-absorption pass (render/ea_render.comp, render/vsEmissionAbsorptionPass.cxx). */
VS_CONST uint VS_EA_VOLUME = 0u;
VS_CONST uint VS_EA_TF = 1u;             /* rgba32f texel buffer: the transfer function's entries */
VS_CONST uint VS_EA_PARAMS = 2u;         /* storage buffer: VsEmissionAbsorptionParams */
VS_CONST uint VS_EA_DEPTH = 3u;
VS_CONST uint VS_EA_RESULT = 4u;
VS_CONST uint VS_EA_FACTOR_IMAGE = 5u;
VS_CONST uint VS_EA_LIGHT = 6u;          /* rgba32f image: the light volume (vsLightVolume.h), read by the lit
                                            modes (VS_EA_LIGHTING_*; a 1-texel placeholder otherwise) */
VS_CONST uint VS_EA_BRICKS = 7u;         /* rgba32f image: the majorant grid's tracking image, for empty-space
                                            skipping (a 1-texel placeholder without majorants) */
VS_CONST uint VS_EA_ENVIRONMENT = 8u;    /* rgba32f texel buffer: the environment's radiance per texel of its
                                            equal-area map (VS_EA_DISPLAY_ENVIRONMENT; a placeholder otherwise) */
VS_CONST uint VS_EA_DISPLAY = 9u;        /* storage buffer: the window image (VS_EA_DISPLAY_IMAGE; a placeholder
                                            otherwise) */
VS_CONST uint VS_EA_LIGHT_TRANSMITTANCE = 10u; /* rgba32f image: the light volume's transmittance towards each
                                            scene light (VS_LIGHTMS_TRANSMITTANCE's layout), read by the preview
                                            with P.lightCount > 0 (a 1-texel placeholder otherwise) */
VS_CONST uint VS_EA_LIGHT_MOMENT = 11u;  /* rgba32f image: the light volume's band-1 moment (3 or 6 layers of its cells,
                                            LightVolume::Moment), read by the preview with P.anisotropy != 0 (issue 39;
                                            a 1-texel placeholder otherwise) */
VS_CONST uint VS_EA_BINDING_COUNT = 12u;

/* The sweeps' march along each direction (visibility/sweep_march.glsl: the full-resolution volume
 * or, VS_SWEEP_POOLED, the pooled extinction volume and its occupancy). */
VS_CONST uint VS_SWEEP_VOLUME = 0u;      /* the volume, or the pooled extinction */
VS_CONST uint VS_SWEEP_TF = 1u;
VS_CONST uint VS_SWEEP_MAJORANT = 2u;    /* the majorant bricks, or the pooled volume's occupancy */
VS_CONST uint VS_SWEEP_GLOBALS = 3u;     /* storage buffer: VsSweepParams */
VS_CONST uint VS_SWEEP_DIRECTIONS = 4u;  /* storage buffer: VsSweepDirection per direction */
VS_CONST uint VS_SWEEP_STATE = 5u;       /* storage buffer: visibility per ray between chunks */
VS_CONST uint VS_SWEEP_STACK = 6u;       /* storage buffer: the kernel stack */
VS_CONST uint VS_SWEEP_FACTOR_IMAGE = 7u; /* full resolution only: the extinction factor */
VS_CONST uint VS_SWEEP_BINDING_COUNT = 8u;
VS_CONST uint VS_SWEEP_POOLED_BINDING_COUNT = 7u;

/* The sweeps' filter of the kernel stack (visibility/sweep_filter.comp). */
VS_CONST uint VS_FILTER_GLOBALS = 0u;
VS_CONST uint VS_FILTER_DIRECTIONS = 1u;
VS_CONST uint VS_FILTER_STACK = 2u;      /* r32f texel buffer: the kernel stack */
VS_CONST uint VS_FILTER_FILTERED = 3u;   /* storage buffer */
VS_CONST uint VS_FILTER_BINDING_COUNT = 4u;

/* The sweeps' projection of the filtered stack into the grid (visibility/sweep_project.glsl). */
VS_CONST uint VS_PROJECT_GLOBALS = 0u;
VS_CONST uint VS_PROJECT_DIRECTIONS = 1u;
VS_CONST uint VS_PROJECT_FILTERED = 2u;  /* r32f texel buffer: sweep_filter.comp's output */
VS_CONST uint VS_PROJECT_VISIBILITY = 3u; /* the grid's image (its storage format) */
VS_CONST uint VS_PROJECT_BINDING_COUNT = 4u;

/* The pooled extinction volume (visibility/sweep_pool.comp) and its occupancy
 * (visibility/sweep_pool_occupancy.comp). */
VS_CONST uint VS_POOL_VOLUME = 0u;
VS_CONST uint VS_POOL_TF = 1u;
VS_CONST uint VS_POOL_POOLED = 2u;
VS_CONST uint VS_POOL_FACTOR_IMAGE = 3u;
VS_CONST uint VS_POOL_QUADS = 4u; /* an integer-coded volume's quads (vsDeviceVolume.h), read instead of the floats */
VS_CONST uint VS_POOL_BINDING_COUNT = 5u;
VS_CONST uint VS_OCCUPANCY_POOLED = 0u;
VS_CONST uint VS_OCCUPANCY_OUTPUT = 1u;
VS_CONST uint VS_OCCUPANCY_BINDING_COUNT = 2u;

/* Brute-force visibility, the sweeps' reference (visibility/visibility_bruteforce.comp). */
VS_CONST uint VS_BRUTE_VOLUME = 0u;
VS_CONST uint VS_BRUTE_TF = 1u;
VS_CONST uint VS_BRUTE_MAJORANT = 2u;
VS_CONST uint VS_BRUTE_GLOBALS = 3u;
VS_CONST uint VS_BRUTE_VISIBILITY = 4u;
VS_CONST uint VS_BRUTE_FACTOR_IMAGE = 5u;
VS_CONST uint VS_BRUTE_BINDING_COUNT = 6u;

/* The direction table (visibility/direction_table.glsl, visibility/vsDirectionTable.cxx). */
VS_CONST uint VS_TABLE_VISIBILITY = 0u;
VS_CONST uint VS_TABLE_MIPS = 1u;
VS_CONST uint VS_TABLE_OUTPUT = 2u;
VS_CONST uint VS_TABLE_SOURCES = 3u;
VS_CONST uint VS_TABLE_BINDING_COUNT = 4u;

/* The light volume (visibility/light_volume.glsl, visibility/vsLightVolume.cxx): per visibility cell,
 * the sum over the grid's directions of V(cell, n) times the environment's radiance integrated over
 * direction n's texel. Push constants: VsLightVolumeParams (light_volume_params.h). */
VS_CONST uint VS_LIGHT_VISIBILITY = 0u;  /* the visibility grid (its storage format) */
VS_CONST uint VS_LIGHT_SOURCES = 1u;     /* storage buffer: VisibilityGrid::DirectionSources */
VS_CONST uint VS_LIGHT_RADIANCE = 2u;    /* storage buffer: vec4 per direction, rgb = E_n (radiance x sr); then
                                            (the moment's build) vec4 per direction, xyz = w_n, its world direction */
VS_CONST uint VS_LIGHT_OUTPUT = 3u;      /* rgba32f image, one texel per cell: the light volume */
VS_CONST uint VS_LIGHT_MOMENT = 4u;      /* rgba32f image of 3 (or 6) layers of cells: the first order's band-1
                                            moment (vsLightVolume.h Moment(); written with specialization constant
                                            1, and 2: layers 3 .. 5 the first order's M and I apart) */
VS_CONST uint VS_LIGHT_BINDING_COUNT = 5u;

/* The light volume's multiple scattering (vsLightVolume.h): the per-cell albedo (light_volume_albedo.comp)
 * and one order of scattering per dispatch (light_volume_scatter.glsl). */
VS_CONST uint VS_LIGHTMS_VOLUME = 0u;     /* r32f image: the volume (albedo pass) */
VS_CONST uint VS_LIGHTMS_TF = 1u;         /* texel buffer of rgba32f entries: the transfer function (albedo pass) */
VS_CONST uint VS_LIGHTMS_PARAMS = 2u;     /* storage buffer: VsLightAlbedoParams (albedo pass) */
VS_CONST uint VS_LIGHTMS_ALBEDO = 3u;     /* rgba32f image per cell: rgb the albedo, a the mean extinction */
VS_CONST uint VS_LIGHTMS_LIGHT = 4u;      /* rgba32f image per cell: the light volume (the total; a untouched) */
VS_CONST uint VS_LIGHTMS_EMIT_IN = 5u;    /* rgba32f image per cell: rgb mean extinction x albedo x I_k, a the
                                             mean extinction */
VS_CONST uint VS_LIGHTMS_EMIT_OUT = 6u;   /* the same of order k + 1 */
VS_CONST uint VS_LIGHTMS_VISIBILITY = 7u; /* the visibility grid (scatter pass; its storage format) */
VS_CONST uint VS_LIGHTMS_SOURCES = 8u;    /* storage buffer: VisibilityGrid::DirectionSources */
VS_CONST uint VS_LIGHTMS_STEPS = 9u;      /* storage buffer: vec4 per direction, xyz its step in cells */
VS_CONST uint VS_LIGHTMS_ORDER_IN = 10u;  /* rgba32f image per cell: rgb I_k (the tail's ratio) */
VS_CONST uint VS_LIGHTMS_ORDER_OUT = 11u; /* the same of order k + 1 */
VS_CONST uint VS_LIGHTMS_DIRECT = 12u;    /* rgba32f image per cell: rgb the scene lights' direct light sum_l T_l E_l
                                             (light_volume_lights.comp; the albedo pass adds it to the first order) */
VS_CONST uint VS_LIGHTMS_TRANSMITTANCE = 13u; /* rgba32f image of cells.x x cells.y x 2 cells.z: per cell the
                                             transmittance towards light l at z + (l / 4) cells.z, component l % 4 */
VS_CONST uint VS_LIGHTMS_SCENE = 14u;     /* storage buffer: VsLightSceneParams (light_volume_lights.comp) */
VS_CONST uint VS_LIGHTMS_MOMENT = 15u;    /* rgba32f image of 3 layers of cells: the first order's band-1 moment M_1
                                             (vsLightVolume.h Moment()'s layout; read by the scatter pass with the
                                             phase's anisotropy) */
VS_CONST uint VS_LIGHTMS_MOMENT_SUM = 16u; /* the same layout: the band-1 moment of the orders 2 .. k + 1 (their sum) */
VS_CONST uint VS_LIGHTMS_ORDER_MOMENT = 17u; /* the same layout: the band-1 moment of order k + 1 (the tail's) */
VS_CONST uint VS_LIGHTMS_BINDING_COUNT = 18u;

/* The majorant bricks' scalar ranges (volume/majorant_minmax.comp, volume/vsMajorantGrid.cxx). */
VS_CONST uint VS_RANGES_VOLUME = 0u;
VS_CONST uint VS_RANGES_OUTPUT = 1u;
VS_CONST uint VS_RANGES_BINDING_COUNT = 2u;

/* An integer-coded volume's float image, made from its quads on first use (volume/volume_from_quads.comp,
 * volume/vsDeviceVolume.cxx). Push constants: VsQuadsPush (quads_params.h). */
VS_CONST uint VS_QUADS_INPUT = 0u;  /* r32ui image: the quads */
VS_CONST uint VS_QUADS_OUTPUT = 1u; /* r32f image: the scalars */
VS_CONST uint VS_QUADS_BINDING_COUNT = 2u;

/* The display's guided filter of the estimate (render/denoise.comp, render/vsDenoisePass.cxx). Push
 * constants: VsDenoiseParams (denoise_params.h). */
VS_CONST uint VS_DENOISE_INPUT = 0u;  /* storage buffer of vec4 planes, w x h each: the estimate, the guide, the
                                         estimate's variance (of its mean, per channel) */
VS_CONST uint VS_DENOISE_SRC = 1u;    /* storage buffer of vec4 planes: what a stage reads */
VS_CONST uint VS_DENOISE_DST = 2u;    /* storage buffer of vec4 planes: what a stage writes */
VS_CONST uint VS_DENOISE_OUTPUT = 3u; /* storage buffer, vec4 per pixel: the filtered estimate (alpha its own) */
VS_CONST uint VS_DENOISE_BINDING_COUNT = 4u;

VS_NAMESPACE_END

#endif
