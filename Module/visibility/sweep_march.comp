#version 460
#extension GL_GOOGLE_include_directive : require
/* The visibility sweep's march over the full-resolution volume (post-classified samples). */
#include "sweep_march.glsl"
