#version 460
#extension GL_GOOGLE_include_directive : require
/* The light volume (light_volume.glsl) from a visibility grid stored as r8. */
#define VS_VIS_FORMAT r8
#include "light_volume.glsl"
