/*
 * display_transform.h — the display transform of linear radiance, written once for the host (the
 * window image of the Monte Carlo estimate, the environment background) and the device (the
 * preview's window image, ea_render.comp): exposure, the filmic tone curve (Narkowicz's fit of
 * ACES) or a clamp, then the sRGB transfer function; and the premultiplied window pixel of a
 * radiance image under the coverage alpha.
 */
#ifndef VS_DISPLAY_TRANSFORM_H
#define VS_DISPLAY_TRANSFORM_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

VS_FUNC float vs_filmic(float x)
{
  return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

VS_FUNC float vs_to_srgb(float x)
{
  x = clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

/* The display value in [0, 1] of radiance `l` already multiplied by the exposure. */
VS_FUNC float vs_display_value(float l, bool toneMapping)
{
  return vs_to_srgb(toneMapping ? vs_filmic(l) : min(l, 1.0f));
}

VS_FUNC vec3 vs_display_rgb(vec3 l, bool toneMapping)
{
  return vec3(vs_display_value(l.x, toneMapping), vs_display_value(l.y, toneMapping),
    vs_display_value(l.z, toneMapping));
}

/* The premultiplied window pixel of radiance (rgb, alpha = the coverage 1 - T). A pixel that sees
 * the environment (`seesEnvironment`: the environment seen through the volume is in its rgb) is
 * either composited over the environment behind it (`composite`; `background` its display colour)
 * or paints it with `opaqueAlpha`; any other pixel is drawn with its coverage.
 * Composited: the tone-mapped full radiance F(L) over what is behind, drawn with the coverage a as
 * C = F(L) - (1 - a) B, so that over the skybox (which shows B) the pixel is F(L) as in the opaque
 * image, and what VTK drew in front of the skybox shows through with the transmittance 1 - a. C is
 * clamped at 0; it is rarely below: F(L) >= F(T L_env), and the display transform (sRGB over the
 * filmic curve) is nearly concave with F(0) = 0, so F(T L_env) >= T F(L_env) but for noise. Where
 * no sample met the volume (a = 0) the pixel is what is behind it.
 * Otherwise premultiplied: the radiance of the covered part tone-mapped, then weighed by coverage. */
VS_FUNC vec4 vs_display_pixel(vec4 radiance, bool seesEnvironment, bool composite, vec3 background,
  float opaqueAlpha, float exposure, bool toneMapping)
{
  if (seesEnvironment && composite)
  {
    float a = clamp(radiance.w, 0.0f, 1.0f);
    if (!(a > 0.0f))
      return vec4(0.0f);
    vec3 full = vs_display_rgb(exposure * vec3(radiance), toneMapping);
    return vec4(max(vec3(0.0f), full - (1.0f - a) * background), a);
  }
  float a = clamp(seesEnvironment ? opaqueAlpha : radiance.w, 0.0f, 1.0f);
  if (!(a > 0.0f))
    return vec4(0.0f, 0.0f, 0.0f, a);
  return vec4(a * vs_display_rgb(exposure * vec3(radiance) / a, toneMapping), a);
}

VS_NAMESPACE_END

#endif
