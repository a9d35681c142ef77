#version 460
#extension GL_GOOGLE_include_directive : require
/* Monte Carlo render pass for the strategies that read no visibility grid (Environment, Uniform):
 * the grid strategies' code (direction maps, tables) is left out, which makes the module a quarter
 * smaller and its pipeline about a third faster to create on lavapipe. Auto's first frames and
 * every Environment-sampled frame use it: the first image waits for this pipeline. The grid
 * binding keeps the other modules' layout (MonteCarloPass binds its 1x1 r8 stand-in). */
#define VS_VIS_FORMAT r8
#define VS_NO_GRID
#include "mc_render.glsl"
