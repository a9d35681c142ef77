/*
 * environment_display.glsl — GLSL-only: the environment seen directly (the background behind the
 * volume), bilinear between the texels of its equal-area map so that it does not look blocky where a
 * texel spans several pixels. Written once for the Monte Carlo kernel (mc_resources.glsl) and the
 * emission-absorption pass's preview (ea_render.comp); the host's twin for its own background is
 * vs::CoverageComposite::EnvironmentRadiance, from the same octahedral.h functions.
 * `environment`: the radiance per texel (rgba32f texels, DeviceEnvironment::Radiance) of an n x n map.
 */
#ifndef VS_ENVIRONMENT_DISPLAY_GLSL
#define VS_ENVIRONMENT_DISPLAY_GLSL
#include "octahedral.h"

vec3 vs_environment_bilinear(samplerBuffer environment, uint n, vec3 w)
{
  vec2 uv = vs_dir_to_octa(w);
  vec3 sum = vec3(0.0);
  for (uint c = 0u; c < 4u; ++c)
  {
    float weight;
    uvec2 t = vs_octa_bilinear_texel(uv, n, c, weight);
    sum += weight * texelFetch(environment, int(t.y * n + t.x)).rgb;
  }
  return sum;
}

#endif
