#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * light_volume_albedo.comp — the light volume's multiple scattering (vsLightVolume.h), its first pass:
 * per visibility cell, the single-scattering albedo the cell scatters with, the extinction-weighted mean
 * a = sum sigma_t(x) albedo(x) / sum sigma_t(x) over samplesPerAxis^3 fixed stratified points of the cell
 * (the volume interpolated as every pass reads it, classified by the transfer function), and the mean
 * extinction sigma; and the first order's emission (sigma a I_1, sigma) and I_1 (the single-scattering
 * light volume), which the first order of scattering reads (light_volume_scatter.glsl). One invocation
 * per cell; nothing random: the same inputs give the same values.
 * With P.lit (VTK's lights, issue 38), the lights' direct light sum_l T_l E_l of the cell
 * (light_volume_lights.comp) joins I_1 in the first order's emission and light, not the total (the
 * preview lights the first order itself, towards each light): the lights' multiple scattering.
 */
#include "bindings.h"
#include "light_volume_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = VS_LIGHTMS_VOLUME, r32f) uniform readonly image3D uVolume;
layout(binding = VS_LIGHTMS_TF) uniform samplerBuffer uTF;
layout(std430, binding = VS_LIGHTMS_PARAMS) readonly buffer Params { VsLightAlbedoParams P; };
layout(binding = VS_LIGHTMS_ALBEDO, rgba32f) uniform writeonly image3D uAlbedo;
layout(binding = VS_LIGHTMS_LIGHT, rgba32f) uniform readonly image3D uLight;
layout(binding = VS_LIGHTMS_EMIT_OUT, rgba32f) uniform writeonly image3D uEmit;
layout(binding = VS_LIGHTMS_ORDER_OUT, rgba32f) uniform writeonly image3D uOrder;
layout(binding = VS_LIGHTMS_DIRECT, rgba32f) uniform readonly image3D uDirect; /* read with P.lit */
#define VS_TF_ENTRY_TEXELS
#include "volume_access.glsl"

void main()
{
  uvec3 cell = gl_GlobalInvocationID;
  if (any(greaterThanEqual(cell, P.cells)))
    return;
  ivec3 dims = ivec3(P.volume.dims);
  uint S = max(P.samplesPerAxis, 1u);
  vec3 weighted = vec3(0.0);
  float extinction = 0.0;
  for (uint k = 0u; k < S; ++k)
    for (uint j = 0u; j < S; ++j)
      for (uint i = 0u; i < S; ++i)
      {
        vec3 x = P.volume.boxMin + (vec3(cell) + (vec3(i, j, k) + 0.5) / float(S)) * P.cellSize;
        vec4 c = vs_classify(vs_sample(x, dims, P.volume.interpolation), P.volume.tf);
        weighted += c.w * c.rgb;
        extinction += c.w;
      }
  vec3 albedo = extinction > 0.0 ? clamp(weighted / extinction, vec3(0.0), vec3(1.0)) : vec3(0.0);
  float sigma = extinction / float(S * S * S);
  imageStore(uAlbedo, ivec3(cell), vec4(albedo, sigma));
  vec3 light = imageLoad(uLight, ivec3(cell)).rgb;
  if (P.lit != 0u)
    light += imageLoad(uDirect, ivec3(cell)).rgb;
  imageStore(uEmit, ivec3(cell), vec4(sigma * albedo * light, sigma));
  imageStore(uOrder, ivec3(cell), vec4(light, 0.0));
}
