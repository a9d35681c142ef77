/*
 * surface_scattering.glsl — hybrid scattering (issue 38): at a scattering event of the path kernel
 * (mc_path.glsl), with probability P_s(x) (microfacet.h vs_surface_probability: VTK's
 * VolumetricScatteringBlending, the normalised gradient magnitude and the opacity at x) the event
 * scatters off a surface whose normal is the scalar's gradient (vs_world_gradient, the one the
 * emission-absorption pass shades with), by the BRDF of microfacet.h (Lambert coloured by the albedo plus
 * a white GGX lobe); else by the Henyey-Greenstein phase function, weighted by the albedo. The event's
 * scattering kernel is the mixture
 *     k(w) = (1 - P_s) albedo f_HG(dw . w) + P_s f_r(-dw, w) |n . w|,
 * which next-event estimation evaluates towards each light direction and the continuation samples
 * (P_s picks the lobe; the path's weight is k / p with p the mixture's density, and the power heuristic
 * weighs p against the light pdf). Compiled only into the pipelines with VS_SPEC_SURFACE (the property's
 * ShadeOn with a blending below 2): the others keep the volumetric kernel's code and bits.
 * Included once, by mc_render.glsl, before light_samples.
 */
#include "microfacet.h"

/* The settings (P.surface*), loaded once per invocation by surface_load. */
float gSurfaceBlending, gSurfaceDiffuse, gSurfaceSpecular, gSurfaceRoughness, gGradientScale, gOpacityDistance;

/* The event being scattered (surface_event): P_s, the unit gradient, the albedo. */
float gEventSurface = 0.0;
vec3 gEventNormal = vec3(0.0, 0.0, 1.0);
vec3 gEventAlbedo = vec3(0.0);

void surface_load()
{
  gSurfaceBlending = P.surfaceBlending;
  gSurfaceDiffuse = P.surfaceDiffuse;
  gSurfaceSpecular = P.surfaceSpecular;
  gSurfaceRoughness = P.surfaceRoughness;
  gGradientScale = P.gradientScale;
  gOpacityDistance = P.opacityDistance;
}

/* Sets up the event at index-space point x of albedo `albedo`: its surface probability and normal
 * (P_s 0 where the gradient is 0 or not finite: no normal). */
void surface_event(vec3 x, vec3 albedo)
{
  gEventAlbedo = albedo;
  gEventSurface = 0.0;
  gEventNormal = vec3(0.0, 0.0, 1.0);
  vec3 gw = vs_world_gradient(x, gDims, gInterpolation, gWorldToIndex);
  float len = length(gw);
  if (!(len > 0.0) || isinf(len))
    return;
  float g = min(1.0, len * gGradientScale);
  float sigma = vs_classify_extinction(kernel_sample(x), gTF) * kernel_factor(x);
  float alpha = 1.0 - exp(-sigma * gOpacityDistance);
  gEventSurface = vs_surface_probability(gSurfaceBlending, g, isnan(alpha) ? 0.0 : alpha);
  gEventNormal = gw / len;
}

/* The event's kernel k(w) towards world direction w for a path that arrived along dw, and the density
 * `pdf` of event_sample's direction w. */
vec3 event_kernel(vec3 dw, vec3 w, out float pdf)
{
  float phase = vs_hg_pdf(dot(dw, w), gAnisotropy);
  float ps = gEventSurface;
  vec3 k = ((1.0 - ps) * phase) * gEventAlbedo;
  pdf = (1.0 - ps) * phase;
  if (ps > 0.0)
  {
    vec3 kd = gEventAlbedo * gSurfaceDiffuse;
    vec3 wo = -dw;
    k += ps * abs(dot(gEventNormal, w)) *
      vs_surface_brdf(gEventNormal, wo, w, kd, gSurfaceSpecular, gSurfaceRoughness);
    pdf += ps * vs_surface_pdf(gEventNormal, wo, w, kd, gSurfaceSpecular, gSurfaceRoughness);
  }
  return k;
}

/* The continuation's direction from the mixture (the surface lobe with probability P_s, else the phase),
 * with its kernel value and its mixture density. */
vec3 event_sample(vec3 dw, inout VsRng rng, out vec3 kernel, out float pdf)
{
  vec3 w;
  float lobePdf;
  float choice = vs_rng_float(rng);
  vec2 u = vs_rng_vec2(rng);
  if (choice < gEventSurface)
    w = vs_sample_surface(gEventNormal, -dw, gEventAlbedo * gSurfaceDiffuse, gSurfaceSpecular, gSurfaceRoughness, u,
      lobePdf);
  else
    w = vs_sample_hg(dw, gAnisotropy, u, lobePdf);
  kernel = event_kernel(dw, w, pdf);
  return w;
}
