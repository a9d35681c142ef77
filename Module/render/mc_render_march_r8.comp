#version 460
#extension GL_GOOGLE_include_directive : require
/* Monte Carlo render pass reading a visibility grid stored as r8, with Kettunen's ray-marched
 * shadow rays compiled in (VS_SPEC_TRANSMITTANCE selects them; TransmittanceEstimator RayMarching). */
#define VS_VIS_FORMAT r8
#define VS_RAY_MARCHING
#include "mc_render.glsl"
