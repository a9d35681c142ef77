#version 460
#extension GL_GOOGLE_include_directive : require
/* The visibility sweep's march over the pooled extinction volume (sweep_pool.comp). */
#define VS_SWEEP_POOLED 1
#include "sweep_march.glsl"
