#version 460
#extension GL_GOOGLE_include_directive : require
/* The Monte Carlo pass (r8 visibility) instrumented to count its volume, majorant and
 * visibility reads, for `vissweep bench overhead`. Same samples as mc_render_r8. */
#define VS_VIS_FORMAT r8
#define VS_COUNT_LOOKUPS
#include "mc_render.glsl"
