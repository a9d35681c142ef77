#version 460
#extension GL_GOOGLE_include_directive : require
/* The direction table (direction_table.glsl) from a visibility grid stored as r16. */
#define VS_VIS_FORMAT r16
#include "direction_table.glsl"
