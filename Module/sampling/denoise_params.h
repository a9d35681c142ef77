/*
 * denoise_params.h — the display's edge-aware filter of the Monte Carlo estimate (render/denoise.comp,
 * render/vsDenoisePass.cxx; issue 39): a guided filter (He, Sun and Tang, "Guided Image Filtering",
 * ECCV 2010 / TPAMI 2013) whose guide is the noise-free preview of the same view. In every window of
 * (2r + 1)^2 pixels each channel of the estimate m is modelled as a linear function of the preview's g,
 * m ~ a g + b, fitted by least squares with a Gaussian prior on the slope around 1 (the preview is an
 * image of the same light): with sigma^2 the window's mean variance of the estimate's pixels (the
 * accumulator's per-sample variance over its samples) and N = (2r + 1)^2 pixels,
 *
 *     a = (cov(g, m) + lambda) / (var(g) + lambda),   b = mean(m) - a mean(g),
 *     lambda = sigma^2 / (N tau^2)                      (tau: the slope's prior spread),
 *
 * the posterior mean of a under that prior. A noisy window (large sigma^2) keeps the preview's shape
 * (a -> 1) and takes its level from the estimate; a window the samples resolve fits the estimate's own
 * slope. Each pixel's output is the mean of the (a, b) of the windows that hold it applied to its own
 * g: edges of the guide stay sharp, the estimate's noise is averaged over ~N pixels. Pixels without
 * variance (exact: the environment seen beside the volume) are left out of the fits (N counts the others)
 * and shown as they are. The push-constant
 * block is laid out identically in std430 GLSL and C++ (named 4-byte fields).
 */
#ifndef VS_DENOISE_PARAMS_H
#define VS_DENOISE_PARAMS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The stages (denoise.comp's specialization constant 0), in their order: the moments of each pixel,
 * a box mean along one axis (run per axis, for the moments and again for the coefficients), the
 * coefficients from the moments' window means, the output from the coefficients' window means. */
VS_CONST uint VS_DENOISE_STAGE_MOMENTS = 0u;
VS_CONST uint VS_DENOISE_STAGE_BOX = 1u;
VS_CONST uint VS_DENOISE_STAGE_COEFFICIENTS = 2u;
VS_CONST uint VS_DENOISE_STAGE_OUTPUT = 3u;
/* Planes of vec4 per pixel: the moments (g, m, g g, g m, sigma^2; rgb each) and the coefficients (a, b). */
VS_CONST uint VS_DENOISE_MOMENT_PLANES = 5u;
VS_CONST uint VS_DENOISE_COEFFICIENT_PLANES = 2u;

struct VsDenoiseParams
{
  uint width;
  uint height;
  uint radius;      /* the window's half width r */
  uint planes;      /* the box stage's planes */
  uint axis;        /* the box stage's axis: 0 along rows (x), 1 along columns (y) */
  float priorScale; /* 1 / (N tau^2): lambda = priorScale x sigma^2 */
  float unused0;
  float unused1;
};

/* Whether a pixel's estimate is noisy: a variance (of its mean) above 0, but for float's rounding. The
 * others are exact (the caller sets their variance to 0: the environment seen past the volume, empty
 * background, every sample the same): they take no part in the fits and are shown as they are. */
VS_FUNC bool vs_denoise_noisy(vec3 m, vec3 s2)
{
  return any(greaterThan(s2, 1e-12f * m * m + vec3(1e-30f)));
}

/* The slope a of one channel from the window means of g, m, g g, g m and sigma^2 (above); b = mean(m) -
 * a mean(g). A tiny floor relative to the guide's level keeps a flat, noise-free window finite (a = 1). */
VS_FUNC float vs_denoise_slope(float meanG, float meanM, float meanGG, float meanGM, float sigma2, float priorScale)
{
  float variance = max(meanGG - meanG * meanG, 0.0f);
  float covariance = meanGM - meanG * meanM;
  float lambda = priorScale * max(sigma2, 0.0f) + 1e-8f * meanG * meanG + 1e-30f;
  return (covariance + lambda) / (variance + lambda);
}

VS_NAMESPACE_END

#endif
