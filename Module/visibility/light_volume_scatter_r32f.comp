#version 460
#extension GL_GOOGLE_include_directive : require
/* One order of the light volume's multiple scattering (light_volume_scatter.glsl) from a visibility grid stored as r32f. */
#define VS_VIS_FORMAT r32f
#include "light_volume_scatter.glsl"
