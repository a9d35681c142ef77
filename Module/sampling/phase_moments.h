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
 *     (1 / 4 pi) (I + 3 g dot(M, d)) + sum_{l >= 2} g^l (band l of L at d):
 * exact up to band 1, the isotropic I / (4 pi) for g = 0. vs_hg_band1_light returns the bracket (the
 * light volume's I as the isotropic preview reads it, with the phase's band 1 added), per channel.
 *
 * A band-1 reconstruction can undershoot: |dot(M, d)| <= I (M is a sum of I's terms times unit
 * vectors), so I + 3 g dot(M, d) >= (1 - 3 |g|) I, negative for |g| > 1/3 where the light comes from one
 * direction only (the phase function's true value never is). It is clamped at 0 per channel: the
 * in-scattered light is never negative, and the clamp only removes light that the truncation made up.
 * For |g| below VS_HG_ISOTROPIC_G the result is I itself, as vs_hg_pdf is exactly isotropic there.
 */
#ifndef VS_PHASE_MOMENTS_H
#define VS_PHASE_MOMENTS_H
#include "vs_prelude.h"
#include "sphere.h"

VS_NAMESPACE_BEGIN

/* HG's band-1 weight (2 l + 1) g^l for l = 1, relative to band 0. */
VS_FUNC float vs_hg_band1_weight(float g)
{
  return 3.0f * g;
}

/* I + 3 g (M . d), clamped at 0, per channel: the in-scattered light towards a camera ray travelling along
 * d (unit), times 4 pi, of light whose band 0 is I (per channel) and band 1 is M = (mx, my, mz) (mx: the
 * channels' moments along x, ...). */
VS_FUNC vec3 vs_hg_band1_light(vec3 I, vec3 mx, vec3 my, vec3 mz, vec3 d, float g)
{
  if (abs(g) < VS_HG_ISOTROPIC_G)
  {
    return I;
  }
  vec3 md = mx * d.x + my * d.y + mz * d.z;
  return max(I + vs_hg_band1_weight(g) * md, vec3(0.0f));
}

VS_NAMESPACE_END

#endif
