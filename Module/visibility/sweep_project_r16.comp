#version 460
#extension GL_GOOGLE_include_directive : require
/* Visibility sweep projection into a grid stored as r16. */
#define VS_VIS_FORMAT r16
#include "sweep_project.glsl"
