#version 460
#extension GL_GOOGLE_include_directive : require
/* Monte Carlo render pass reading a visibility grid stored as r32f. */
#define VS_VIS_FORMAT r32f
#include "mc_render.glsl"
