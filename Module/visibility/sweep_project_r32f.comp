#version 460
#extension GL_GOOGLE_include_directive : require
/* Visibility sweep projection into a grid stored as r32f. */
#define VS_VIS_FORMAT r32f
#include "sweep_project.glsl"
