/*
 * mis.h — combining the two ways a path finds the environment at a scattering event (Veach 1997,
 * ch. 9), and when a path may end (Russian roulette). Used by the path estimator (mc_path.glsl).
 *
 * At an event the environment is reached two ways: n light directions from the strategy (pdf p_L,
 * each with a shadow ray: next-event estimation) and the continuation from the phase function (pdf
 * p_P, scored if it escapes). With weights w_L + w_P = 1 for every direction, the sum of the two
 * weighted estimates is unbiased whatever the weights (multi-sample MIS). The power heuristic
 * (exponent 2),
 *     w_L(w) = (n p_L)² / ((n p_L)² + p_P²),   w_P(w) = p_P² / ((n p_L)² + p_P²),
 * gives nearly all the weight to whichever pdf is much larger: the sun to light sampling, a strongly
 * forward phase lobe to the continuation. Veach shows it is never much worse than the balance
 * heuristic (exponent 1) and better where one strategy is much better than the other, which is the
 * case here on both sides; pbrt-v4 and Mitsuba 3 use it for the same reason.
 */
#ifndef VS_MIS_H
#define VS_MIS_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The weight of a sample from strategy f (nf samples, pdf fPdf) against strategy g (ng samples,
 * pdf gPdf), power heuristic. A pdf that is 0 or not finite gives the other strategy everything. */
VS_FUNC float vs_power_heuristic(float nf, float fPdf, float ng, float gPdf)
{
  float f = nf * fPdf, g = ng * gPdf;
  if (!(f > 0.0f))
  {
    return 0.0f;
  }
  if (!(g > 0.0f))
  {
    return 1.0f;
  }
  /* Ratios, so that neither square over- or underflows: w = 1 / (1 + (g / f)²). */
  float r = g / f;
  return 1.0f / (1.0f + r * r);
}

/* The same, balance heuristic: nf fPdf / (nf fPdf + ng gPdf). */
VS_FUNC float vs_balance_heuristic(float nf, float fPdf, float ng, float gPdf)
{
  float f = nf * fPdf, g = ng * gPdf;
  if (!(f > 0.0f))
  {
    return 0.0f;
  }
  if (!(g > 0.0f))
  {
    return 1.0f;
  }
  return 1.0f / (1.0f + g / f);
}

/* The probability that a path with throughput `beta` survives Russian roulette after its event
 * `events` (counted from 1): 1 before `rouletteDepth`, then the largest component of the throughput
 * capped at 0.95, so that even albedo 1 (throughput never below 1) ends every path with probability
 * one (Mitsuba 3's rule). The survivor's throughput is divided by it: unbiased. */
VS_FUNC float vs_roulette_survival(vec3 beta, uint events, uint rouletteDepth)
{
  if (events < rouletteDepth)
  {
    return 1.0f;
  }
  float m = max(beta.x, max(beta.y, beta.z));
  return m > 0.0f ? min(m, 0.95f) : 0.0f;
}

VS_NAMESPACE_END

#endif
