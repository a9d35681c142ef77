/*
 * dither.h — a fixed per-pixel offset pattern for deterministic ray marches: interleaved gradient
 * noise (Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014
 * course), a value in [0, 1) per pixel whose neighbours differ as much as they can. A march whose
 * samples all sit at the midpoints of their steps draws the voxel grid and the steps' phase as
 * wood-grain rings and, behind empty-space skipping, as brick-shaped patches; offsetting each pixel's
 * samples by this pattern turns both into a fine dither that is the same in every frame (nothing
 * random: the image stays deterministic).
 */
#ifndef VS_DITHER_H
#define VS_DITHER_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

VS_FUNC float vs_interleaved_gradient_noise(uvec2 pixel)
{
  float v = fract(52.9829189f * fract(0.06711056f * float(pixel.x) + 0.00583715f * float(pixel.y)));
  return min(v, VS_ONE_MINUS_EPSILON);
}

VS_NAMESPACE_END

#endif
