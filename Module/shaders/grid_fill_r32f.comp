#version 460
#extension GL_GOOGLE_include_directive : require
/* Unswept directions of a visibility grid stored as r32f (grid_fill.glsl). */
#define VS_VIS_FORMAT r32f
#include "grid_fill.glsl"
