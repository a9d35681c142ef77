#version 460
#extension GL_GOOGLE_include_directive : require
/* The Monte Carlo pass (r8 visibility) instrumented to count its volume, majorant and
 * visibility reads, for `vissweep bench overhead`. Same samples as mc_render_r8 (and as
 * mc_render_march_r8 with ray-marched shadow rays). */
#define VS_VIS_FORMAT r8
#define VS_COUNT_LOOKUPS
#define VS_RAY_MARCHING
#include "mc_render.glsl"
