/*
 * phase_moments.h — the Henyey-Greenstein phase function applied to light that is known by its first
 * two spherical-harmonic bands (issue 39: the preview's anisotropy towards the environment).
 *
 * The light volume (visibility/vsLightVolume.h) keeps per cell, for the environment's single scattering,
 *     I = sum_n V(n) E_n            (band 0: the incident light integrated over the sphere, radiance x sr)
 *     M = sum_n V(n) E_n w_n        (band 1: its first directional moment, a vector per colour channel)
 * with w_n the direction towards the light's source (sphere.h's convention: a camera ray travelling along d
 * meets light from w at cos theta = dot(d, w); g > 0 favours light from behind the volume).
 *
 * HG's expansion in Legendre polynomials is f(cos) = (1 / 4 pi) sum_l (2 l + 1) g^l P_l(cos), so by the
 * Funk-Hecke theorem the in-scattered light towards the camera, integral f(dot(d, w)) L(w) dw, is
 *     (1 / 4 pi) (I + 3 g dot(M, d)) + sum_{l >= 2} g^l (band l of L at d).
 * Bands 0 and 1 are known; the higher ones are not. Truncating them (the band-1 reconstruction) undershoots
 * below 0 where the light comes from few directions and |g| > 1/3 (I + 3 g M.d >= (1 - 3 |g|) I only), and
 * a clamp at 0 then loses what HG sends backwards (measured on a sun behind a ball with g = -0.6: the
 * preview 43% darker than the estimate). Instead the light is taken as one HG-shaped lobe around M,
 *     L(w) = I f_HG(dot(m, w); rho),   m = M / |M|,  rho = |M| / I (its mean cosine, in [0, 1]),
 * the non-negative field with those two bands whose band l is rho^l. HG convolved with HG is HG with the
 * product of the parameters (the Legendre coefficients multiply), so the in-scattered light is
 *     I f_HG(dot(m, d); g rho)
 * in closed form: bands 0 and 1 exact (I and 3 g M.d), never negative, exact for isotropic light (rho = 0,
 * I / 4 pi) and for light from one direction (rho = 1, f_HG itself), and I / 4 pi for g = 0. The higher
 * bands are those of the lobe (g rho)^l, not the light's: for a sun over a sky (a peak plus a constant) they
 * are too low towards the sun and too high away from it; for light from a uniform hemisphere (a cell in a
 * dense medium's shadow under a constant sky) too high. Compared in units of the isotropic I / 4 pi, with d
 * along m, g = 0.6 (the exact value in brackets): a uniform hemisphere 2.65 [1.75], band 1 unclamped 1.90,
 * the sun-over-sky closed form (I - |M|) / 4 pi + |M| f_HG(m.d; g) 5.5; half the light in a sun, g = 0.9:
 * 4.8 [95], sun-over-sky exact. The lobe is the form without a blow-up (at most f_HG(1; g rho) / f_HG(1; 0)
 * of isotropic, where the sun-over-sky form reaches f_HG(1; g) rho / f_HG(1; 0): 95 at g 0.9, rho 0.5, a
 * glow on the far side of every shadowed cell under the default constant sky). docs/reference.md: the
 * preview's measured bias.
 * vs_hg_lobe_light returns 4 pi times it per channel (the light volume's I as the isotropic preview reads it).
 * For |g| below VS_HG_ISOTROPIC_G the result is I itself, bit for bit.
 */
#ifndef VS_PHASE_MOMENTS_H
#define VS_PHASE_MOMENTS_H
#include "vs_prelude.h"
#include "sphere.h"

VS_NAMESPACE_BEGIN

/* 4 pi I f_HG(dot(m, d); g rho) for one channel: band 0 I, band 1 M (m = M / |M|, rho = |M| / I). */
VS_FUNC float vs_hg_lobe_channel(float I, vec3 M, vec3 d, float g)
{
  float len = length(M);
  if (!(I > 0.0f) || !(len > 0.0f))
  {
    return max(I, 0.0f); /* no light, or isotropic light */
  }
  float rho = min(len / I, 1.0f);
  return I * (4.0f * VS_PI) * vs_hg_pdf(dot(M, d) / len, g * rho);
}

/* The in-scattered light towards a camera ray travelling along d (unit), times 4 pi, of light whose band 0
 * is I (per channel) and band 1 M = (mx, my, mz) (mx: the channels' moments along x, ...): per channel
 * 4 pi I f_HG(dot(m, d); g rho) (above). */
VS_FUNC vec3 vs_hg_lobe_light(vec3 I, vec3 mx, vec3 my, vec3 mz, vec3 d, float g)
{
  if (abs(g) < VS_HG_ISOTROPIC_G)
  {
    return I;
  }
  return vec3(vs_hg_lobe_channel(I.x, vec3(mx.x, my.x, mz.x), d, g),
    vs_hg_lobe_channel(I.y, vec3(mx.y, my.y, mz.y), d, g), vs_hg_lobe_channel(I.z, vec3(mx.z, my.z, mz.z), d, g));
}

/* Similarity (issue 39: the light volume's orders >= 2 under an anisotropic phase; Wyman, Patterson and
 * Zhao's similarity relations, the delta-isotropic phase g delta(forward) + (1 - g) / (4 pi)). Light that has
 * scattered once is carried on in the similar medium: an isotropic phase, the extinction and albedo
 *     sigma_t* = sigma_t (1 - a g),   a* = a (1 - g) / (1 - a g),
 * which keep the absorption sigma_t (1 - a) and the reduced scattering sigma_s (1 - g) (the transport mean
 * free path: the diffusion equation of both media is the same, so their fluence and flux are). Per channel
 * (the albedo is rgb). For g = 0 both are the medium itself. */
VS_FUNC vec3 vs_similar_extinction(float sigma, vec3 albedo, float g)
{
  return sigma * (vec3(1.0f) - g * albedo);
}

VS_FUNC vec3 vs_similar_albedo(vec3 albedo, float g)
{
  return albedo * (1.0f - g) / (vec3(1.0f) - g * albedo);
}

/* The transmittance of a segment in the similar medium from its real one T (in [0, 1]): its optical depth
 * times `ratio`, the segment's sigma_t* / sigma_t per channel (> 0), T^ratio (1 at T = 1, 0 at T = 0). */
VS_FUNC vec3 vs_similar_transmittance(float T, vec3 ratio)
{
  /* one logarithm for the three channels (T = 0: log2 -inf, exp2 0) */
  return exp2(ratio * log2(clamp(T, 0.0f, 1.0f)));
}

VS_NAMESPACE_END

#endif
