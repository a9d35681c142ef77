#version 460
#extension GL_GOOGLE_include_directive : require
/* The light volume (light_volume.glsl) from a visibility grid stored as r32f. */
#define VS_VIS_FORMAT r32f
#include "light_volume.glsl"
