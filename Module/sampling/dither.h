/*
 * dither.h — a fixed per-pixel offset pattern for deterministic ray marches: interleaved gradient
 * noise (Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014
 * course), a value in [0, 1) per pixel whose neighbours differ as much as they can. A march whose
 * samples all sit at the midpoints of their steps draws the voxel grid and the steps' phase as
 * wood-grain rings and, behind empty-space skipping, as brick-shaped patches; offsetting each pixel's
 * samples by this pattern turns both into a fine dither that is the same in every frame (nothing
 * random: the image stays deterministic). vs_dither_offset rotates the pattern per frame, for frames
 * that are averaged (a still view's preview).
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

/* The pattern of frame k: the pixel's offset rotated by k (phi - 1) mod 1 (a Cranley-Patterson rotation
 * by the golden ratio's additive recurrence). Frame 0 is the pattern itself; every pixel's offsets over
 * frames 0..k-1 are spread evenly over [0, 1) (gaps of at most ~2.6 / k), so the mean of k frames
 * integrates each step instead of reading it at one fixed point, and the pattern's beat against the
 * volume's structure (a moire of curved bands at coarse steps) averages out. Deterministic: frame k of
 * a pixel is always the same offset. */
VS_FUNC float vs_dither_offset(uvec2 pixel, uint frame)
{
  float v = fract(vs_interleaved_gradient_noise(pixel) + float(frame % 4096u) * 0.61803398875f);
  return min(v, VS_ONE_MINUS_EPSILON);
}

VS_NAMESPACE_END

#endif
