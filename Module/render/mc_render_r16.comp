#version 460
#extension GL_GOOGLE_include_directive : require
/* Monte Carlo render pass reading a visibility grid stored as r16. */
#define VS_VIS_FORMAT r16
#include "mc_render.glsl"
