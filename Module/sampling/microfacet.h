/*
 * microfacet.h — the surface lobe of hybrid scattering (issue 38; used by the path kernel's
 * surface_scattering.glsl and by the CPU tests): where the scalar's gradient is strong, a scattering
 * event may scatter off a surface whose normal is the gradient instead of by the phase function.
 *
 * The BRDF, two-sided (the side of the normal is the one the outgoing direction wo lies on):
 *     f(wo, wi) = kd / pi + ks D(h) G2(wo, wi) / (4 |n.wo| |n.wi|)     for wi on wo's side, else 0,
 * Lambert plus a normalised GGX (Trowbridge-Reitz) microfacet lobe without Fresnel (F = 1), h the half
 * vector, D the GGX distribution of roughness alpha, G2 Smith's height-correlated masking-shadowing
 * (Heitz 2014, "Understanding the masking-shadowing function"). kd is the diffuse colour (the colour
 * transfer function's albedo times the diffuse weight), ks the specular weight (white, as VTK's
 * specular term). f is symmetric in wo and wi (reciprocal) and, with kd + ks <= 1, its directional
 * albedo  int f |n.wi| dwi = kd + ks E(wo) <= 1  (E <= 1 is the single-scattering GGX lobe's albedo; the
 * energy of light that would bounce between microfacets is lost, most at high roughness and grazing).
 * With ks = 0 the albedo is kd exactly: the white furnace holds.
 *
 * Sampling: with probability pd = lum(kd) / (lum(kd) + ks) a cosine-weighted direction on wo's side,
 * else a GGX half vector h with density D(h) |n.h| reflected about h; the pdf of the mixture over the
 * whole sphere is vs_surface_pdf (a reflected direction below the surface is returned with its pdf; its
 * BRDF is 0).
 *
 * Directions: wo points away from the event towards where the light goes (the negated direction the
 * path arrived along), wi towards where it comes from (the light, or the continuation's direction). The
 * normal n need not face wo.
 *
 * VTK's settings (docs/reference.md "Surface scattering"): roughness from SpecularPower p by Walter et
 * al. 2007's Phong-to-microfacet mapping alpha = sqrt(2 / (p + 2)); kd, ks from Diffuse and Specular,
 * scaled down together so that they sum to at most 1; Ambient has no counterpart (the environment is
 * the ambient light). The probability of a surface event is vs_surface_probability.
 */
#ifndef VS_MICROFACET_H
#define VS_MICROFACET_H
#include "sphere.h"
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* The smallest roughness the lobe takes (a sharper lobe than SpecularPower 128's alpha = 0.124 is not
 * asked for; it keeps D finite in float). */
VS_CONST float VS_MIN_ROUGHNESS = 0.02f;

/* GGX roughness alpha from VTK's SpecularPower p >= 0 (Walter et al. 2007, eq. 33's Phong exponent:
 * alpha = sqrt(2 / (p + 2))), clamped to [VS_MIN_ROUGHNESS, 1]. */
VS_FUNC float vs_roughness_from_specular_power(float p)
{
  float a = sqrt(2.0f / (max(p, 0.0f) + 2.0f));
  return clamp(a, VS_MIN_ROUGHNESS, 1.0f);
}

/* The lobe's diffuse and specular weights (kd scale, ks) from VTK's Diffuse and Specular (each clamped to
 * >= 0), scaled together so that kd + ks <= 1 (energy conservation). */
VS_FUNC vec2 vs_surface_weights(float diffuse, float specular)
{
  float d = max(diffuse, 0.0f), s = max(specular, 0.0f);
  float scale = max(1.0f, d + s);
  return vec2(d / scale, s / scale);
}

/* GGX's normal distribution D(h) at cos(n, h) = c (1/sr, projected: int D(h) (n.h) dh = 1). */
VS_FUNC float vs_ggx_d(float c, float alpha)
{
  float a2 = alpha * alpha;
  float t = c * c * (a2 - 1.0f) + 1.0f;
  return a2 / (VS_PI * t * t);
}

/* Smith's Lambda for GGX at cos(n, v) = c > 0. */
VS_FUNC float vs_ggx_lambda(float c, float alpha)
{
  float c2 = c * c;
  return 0.5f * (sqrt(c2 + alpha * alpha * (1.0f - c2)) / c - 1.0f);
}

/* The BRDF f(wo, wi) (without the cosine), per channel; two-sided, reflection only. */
VS_FUNC vec3 vs_surface_brdf(vec3 n, vec3 wo, vec3 wi, vec3 kd, float ks, float alpha)
{
  float co = dot(n, wo), ci = dot(n, wi);
  if (co < 0.0f)
  {
    co = -co;
    ci = -ci;
  }
  if (!(co > 0.0f) || !(ci > 0.0f))
  {
    return vec3(0.0f);
  }
  vec3 f = kd * VS_INV_PI;
  if (ks > 0.0f)
  {
    vec3 h = normalize(wo + wi);
    float ch = abs(dot(n, h));
    float g2 = 1.0f / (1.0f + vs_ggx_lambda(co, alpha) + vs_ggx_lambda(ci, alpha));
    f += vec3(ks * vs_ggx_d(ch, alpha) * g2 / (4.0f * co * ci));
  }
  return f;
}

/* The probability of choosing the diffuse part when sampling. */
VS_FUNC float vs_surface_diffuse_choice(vec3 kd, float ks)
{
  float d = vs_luminance(kd);
  return d + ks > 0.0f ? d / (d + ks) : 1.0f;
}

/* The density (1/sr, over the whole sphere) of vs_sample_surface's directions wi given wo. */
VS_FUNC float vs_surface_pdf(vec3 n, vec3 wo, vec3 wi, vec3 kd, float ks, float alpha)
{
  float pd = vs_surface_diffuse_choice(kd, ks);
  vec3 m = dot(n, wo) < 0.0f ? -n : n; /* the normal on wo's side */
  float pdf = 0.0f;
  float ci = dot(m, wi);
  if (pd > 0.0f && ci > 0.0f)
  {
    pdf += pd * ci * VS_INV_PI;
  }
  if (pd < 1.0f)
  {
    vec3 s = wo + wi;
    float len = length(s);
    if (len > 0.0f)
    {
      vec3 h = s / len;
      float ch = dot(m, h);
      if (ch < 0.0f)
      {
        h = -h;
        ch = -ch;
      }
      float oh = abs(dot(wo, h));
      if (oh > 0.0f && ch > 0.0f)
      {
        pdf += (1.0f - pd) * vs_ggx_d(ch, alpha) * ch / (4.0f * oh);
      }
    }
  }
  return pdf;
}

/* A direction wi from the lobe's sampling mixture given wo; u in [0, 1)^2 (u.x both chooses the part and,
 * rescaled, samples it). pdf = vs_surface_pdf(n, wo, wi, ...). */
VS_FUNC vec3 vs_sample_surface(vec3 n, vec3 wo, vec3 kd, float ks, float alpha, vec2 u, VS_OUT(float) pdf)
{
  float pd = vs_surface_diffuse_choice(kd, ks);
  vec3 m = dot(n, wo) < 0.0f ? -n : n;
  vec3 wi;
  if (u.x < pd)
  {
    float v = min(u.x / pd, VS_ONE_MINUS_EPSILON);
    wi = vs_direction_around(m, sqrt(1.0f - v), 2.0f * VS_PI * u.y);
  }
  else
  {
    float v = min((u.x - pd) / (1.0f - pd), VS_ONE_MINUS_EPSILON);
    /* tan^2 theta_h = alpha^2 v / (1 - v): cos theta_h = sqrt((1 - v) / (1 + (alpha^2 - 1) v)). */
    float a2 = alpha * alpha;
    float ch = sqrt(max(0.0f, (1.0f - v) / (1.0f + (a2 - 1.0f) * v)));
    vec3 h = vs_direction_around(m, ch, 2.0f * VS_PI * u.y);
    wi = normalize(2.0f * dot(wo, h) * h - wo);
  }
  pdf = vs_surface_pdf(n, wo, wi, kd, ks, alpha);
  return wi;
}

/* The probability that a scattering event is a surface event (issue 38), from the blending b in [0, 2]
 * (VTK 9.2's VolumetricScatteringBlending: its range and direction), the normalised gradient magnitude
 * g in [0, 1] and the opacity a in [0, 1] at the event:
 *     s   = 1 - exp(-25 g)                  (Exposure Render's gradient term, Kroes et al. 2012, its
 *                                            gradient factor 1: no surface where the gradient vanishes)
 *     P_s = s ((1 - b) + b a)               for b in [0, 1]
 *     P_s = s a (2 - b)                     for b in [1, 2]
 * b = 0: a surface wherever the gradient allows; b = 1: Exposure Render's P_s = a s (surfaces where the
 * gradient is strong and the medium opaque); b = 2: never (volumetric only). Continuous and
 * non-increasing in b. (vtkGPUVolumeRayCastMapper blends two shading models' colours per sample with a
 * coefficient of its own, unclamped and discontinuous at b = 1; a probability needs [0, 1].) */
VS_FUNC float vs_surface_probability(float b, float g, float a)
{
  float s = 1.0f - exp(-25.0f * clamp(g, 0.0f, 1.0f));
  float o = clamp(a, 0.0f, 1.0f);
  float bb = clamp(b, 0.0f, 2.0f);
  float share = bb <= 1.0f ? (1.0f - bb) + bb * o : o * (2.0f - bb);
  return s * share;
}

VS_NAMESPACE_END

#endif
