/*
 * sphere.h — sampling directions on the unit sphere: uniform, and the phase
 * functions (isotropic, Henyey-Greenstein).
 *
 * Convention: every pdf here is a density with respect to solid angle (1/sr),
 * so it integrates to 1 over the sphere; a phase function is its own pdf.
 *
 * Uniform sphere: z = 1 - 2 u.x, φ = 2π u.y (Archimedes: z is uniform on
 * [-1,1] for a uniform direction), pdf 1/(4π).
 *
 * Henyey-Greenstein with asymmetry g in (-1,1), as a function of the cosine of
 * the angle between the sampled direction w and an axis a:
 *     p(cos θ) = (1 - g²) / (4π (1 + g² - 2 g cos θ)^{3/2}),  cos θ = dot(a, w).
 * g > 0 puts the density around +a. The sampler inverts the cdf in cos θ
 * (in a form without the usual cancellation, see vs_hg_sample_cos_theta).
 * For |g| < VS_HG_ISOTROPIC_G the sampler and the pdf both become exactly
 * isotropic (cos θ = 2u - 1, the g -> 0 limit of the sampler), so they agree.
 *
 * Which axis to pass: for a camera ray travelling along d that scatters at x,
 * light arrives at x travelling along -w (w = direction towards the light) and
 * leaves travelling along -d, so cos θ (between the two propagation
 * directions) = dot(-w, -d) = dot(d, w): pass a = d and sample w, the shadow
 * ray direction. g > 0 (forward scattering) then favours light from behind.
 */
#ifndef VS_SPHERE_H
#define VS_SPHERE_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* Below this |g| Henyey-Greenstein is treated as isotropic. */
VS_CONST float VS_HG_ISOTROPIC_G = 1e-3f;

/* ---------------------------------------------------------------- uniform */

VS_FUNC float vs_uniform_sphere_pdf()
{
  return VS_INV_4PI;
}

/* u in [0,1)^2 -> a uniformly distributed unit direction. */
VS_FUNC vec3 vs_sample_uniform_sphere(vec2 u)
{
  float z = 1.0f - 2.0f * u.x;
  float r = sqrt(max(0.0f, 1.0f - z * z));
  float phi = 2.0f * VS_PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}

/* ------------------------------------------------------- local frames */

/* An orthonormal basis (t, b, n) around the unit vector n, without branches
 * on the direction (Duff et al., "Building an Orthonormal Basis, Revisited",
 * JCGT 6(1), 2017). */
VS_FUNC void vs_coordinate_frame(vec3 n, VS_OUT(vec3) t, VS_OUT(vec3) b)
{
  float s = vs_copysign(1.0f, n.z);
  float a = -1.0f / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

/* The unit direction at polar cosine cosTheta and azimuth phi around n. */
VS_FUNC vec3 vs_direction_around(vec3 n, float cosTheta, float phi)
{
  vec3 t;
  vec3 b;
  vs_coordinate_frame(n, t, b);
  float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
  return sinTheta * cos(phi) * t + sinTheta * sin(phi) * b + cosTheta * n;
}

/* ------------------------------------------------------------ isotropic */

VS_FUNC float vs_isotropic_phase_pdf()
{
  return VS_INV_4PI;
}

/* ----------------------------------------------------- Henyey-Greenstein */

/* Phase function value = pdf (1/sr) at cos θ = dot(axis, w). */
VS_FUNC float vs_hg_pdf(float cosTheta, float g)
{
  if (abs(g) < VS_HG_ISOTROPIC_G)
  {
    return VS_INV_4PI;
  }
  float denom = max(1.0f + g * g - 2.0f * g * cosTheta, 0.0f);
  return VS_INV_4PI * (1.0f - g * g) / (denom * sqrt(denom));
}

/* Inverse cdf of cos θ under Henyey-Greenstein; u in [0,1), cos θ increasing
 * in u. The usual closed form (1 + g² - ((1 - g²)/(1 - g + 2gu))²)/(2g) loses
 * up to 1e-3 to cancellation at small |g| or g near -1. Multiplying out the
 * square cancels the 1/g exactly:
 *     cos θ = (2u (1 + g²)(1 - g + g u) - (1 - g)²) / (1 - g + 2 g u)²,
 * accurate to ~3e-7 for g >= 0; for g < 0 sample |g| mirrored,
 * cos θ(g, u) = -cos θ(-g, 1 - u). */
VS_FUNC float vs_hg_sample_cos_theta(float g, float u)
{
  if (abs(g) < VS_HG_ISOTROPIC_G)
  {
    return 2.0f * u - 1.0f;
  }
  float a = abs(g);
  float v = g < 0.0f ? 1.0f - u : u;
  float s = 1.0f - a + 2.0f * a * v;
  float c = (2.0f * v * (1.0f + a * a) * (1.0f - a + a * v) - (1.0f - a) * (1.0f - a)) / (s * s);
  return clamp(g < 0.0f ? -c : c, -1.0f, 1.0f);
}

/* A direction w distributed by Henyey-Greenstein around the unit vector axis
 * (cos θ = dot(axis, w)); pdf = vs_hg_pdf(dot(axis, w), g). */
VS_FUNC vec3 vs_sample_hg(vec3 axis, float g, vec2 u, VS_OUT(float) pdf)
{
  float cosTheta = vs_hg_sample_cos_theta(g, u.x);
  pdf = vs_hg_pdf(cosTheta, g);
  return vs_direction_around(axis, cosTheta, 2.0f * VS_PI * u.y);
}

VS_NAMESPACE_END

#endif
