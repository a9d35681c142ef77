#version 460
#extension GL_GOOGLE_include_directive : require
/* The direction table (direction_table.glsl) from a visibility grid stored as r8. */
#define VS_VIS_FORMAT r8
#include "direction_table.glsl"
