#version 460
#extension GL_GOOGLE_include_directive : require
/* The direction table (direction_table.glsl) from a visibility grid stored as r32f. */
#define VS_VIS_FORMAT r32f
#include "direction_table.glsl"
