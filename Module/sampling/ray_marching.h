/*
 * ray_marching.h — the series of Kettunen et al.'s unbiased ray-marching transmittance estimator
 * ("An unbiased ray-marching transmittance estimator", Kettunen, d'Eon, Pantaleoni, Novak,
 * SIGGRAPH 2021), the parts that are pure math (mc_render.glsl's march_transmittance does the rest).
 *
 * T = exp(-tau) = exp(-X0) exp(X0 - tau) = exp(-X0) sum_k (X0 - tau)^k / k!  for any X0 independent
 * of the further estimates. With X0 a jittered ray march of the optical depth (the "bias-corrected"
 * control: exp(-X0) alone is ray marching's biased estimate) and X1, X2, ... independent ray marches
 * (each unbiased for tau), prod_{i<=k} (X0 - Xi) is unbiased for (X0 - tau)^k given X0, so
 *   T^ = exp(-X0) sum_{k=0}^{N} prod_{i=1}^{k} (X0 - Xi) / (k! P(N >= k))
 * is unbiased for T for any random order N with P(N >= k) > 0 for all k (no truncation). The order is
 * drawn by their aggressive Bhanot & Kennedy roulette: order 0 with probability pZ, else at least K
 * terms, then term k continues with probability min(1, c / k). The march takes Kettunen's "p-series
 * CMF" sample count for the ray's optical depth.
 */
#ifndef VS_RAY_MARCHING_H
#define VS_RAY_MARCHING_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The roulette's constants (Kettunen et al. 2021, Sec. 5: aggressive BK roulette). */
VS_CONST float VS_RM_ORDER_ZERO = 0.9f; /* pZ: the probability of the order-0 estimate exp(-X0) */
VS_CONST uint VS_RM_MIN_ORDER = 2u;    /* K: once past order 0, the terms up to K are all taken */
VS_CONST float VS_RM_BK_C = 2.0f;       /* c: term k > K is taken with probability min(1, c / k) */
/* The march's sample count is capped (any count keeps the estimator unbiased): bounds the work of a
 * ray through a hostile extinction, which the trackers' step budget ends anyway. */
VS_CONST float VS_RM_MAX_SAMPLES = 256.0f;

/* The probability of taking term k of the series given term k - 1 was taken (k >= 1):
 * P(N >= k) / P(N >= k - 1). */
VS_FUNC float vs_rm_continue_probability(uint k)
{
  if (k == 1u)
    return 1.0f - VS_RM_ORDER_ZERO;
  if (k <= VS_RM_MIN_ORDER)
    return 1.0f;
  return min(1.0f, VS_RM_BK_C / float(k));
}

/* P(N >= k), the product of the conditional probabilities (for the tests; the shader multiplies
 * as it goes). */
VS_FUNC float vs_rm_order_probability(uint k)
{
  float p = 1.0f;
  for (uint j = 1u; j <= k; ++j)
    p *= vs_rm_continue_probability(j);
  return p;
}

/* The factor term k's product takes on when term k is taken: (X0 - Xk) / (k q_k), so that the
 * running product is prod (X0 - Xi) / (k! P(N >= k)). */
VS_FUNC float vs_rm_term_factor(float x0, float xk, uint k)
{
  return (x0 - xk) / (float(k) * vs_rm_continue_probability(k));
}

/* Kettunen et al.'s ray-march sample count for optical depth tau: the cube root of their cubic
 * N_CMF(tau) = (tau + 0.015)(tau + 0.65)(tau + 60.3) (rounded up), divided by 1 + the expected
 * number of further marches of the roulette above (E[N] = 0.31945 in their paper), at least 1,
 * at most VS_RM_MAX_SAMPLES. Large tau: about tau + 20 samples per march; tau = 1: 4. */
VS_FUNC float vs_rm_sample_count(float tau)
{
  float x = max(tau, 0.0f);
  float cubic = ((x + 60.965f) * x + 40.10925f) * x + 0.587925f;
  float n = ceil(pow(cubic, 1.0f / 3.0f)) / (1.0f + 0.31945f);
  return clamp(floor(n + 0.5f), 1.0f, VS_RM_MAX_SAMPLES);
}

VS_NAMESPACE_END

#endif
