#version 460
#extension GL_GOOGLE_include_directive : require
/* Visibility sweep projection into a grid stored as r8. */
#define VS_VIS_FORMAT r8
#include "sweep_project.glsl"
