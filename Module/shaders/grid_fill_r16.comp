#version 460
#extension GL_GOOGLE_include_directive : require
/* Unswept directions of a visibility grid stored as r16 (grid_fill.glsl). */
#define VS_VIS_FORMAT r16
#include "grid_fill.glsl"
