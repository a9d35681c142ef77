#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * light_volume_lights.comp — VTK's lights in the light volume (issue 38; vsLightVolume.h): per visibility
 * cell and scene light l (sampling/scene_lights.h), the transmittance T_l from the cell's centre towards
 * the light, to the light (a positional one) or to where the ray leaves the volume (its box, cropping and
 * clip planes), marched through the volume as every pass reads it (the scalar interpolated, classified by
 * the transfer function) in steps of P.step world units, each sampled at its midpoint: nothing random,
 * the same inputs give the same values. Writes T_l into uTransmittance (texel (x, y, z + (l / 4) cells.z),
 * component l % 4), which the preview interpolates between the cells' centres to light each sample
 * directly (ea_render.comp), and the cell's direct light sum_l T_l E_l (E_l the light's irradiance at the
 * centre) into uDirect: the first order of the lights' multiple scattering (the albedo pass adds it to
 * the environment's I_1 where the orders start; the preview does not read it, it lights the first
 * order itself, with the phase function towards each light). One invocation per cell.
 */
#include "bindings.h"
#include "light_volume_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = VS_LIGHTMS_VOLUME, r32f) uniform readonly image3D uVolume;
layout(binding = VS_LIGHTMS_TF) uniform samplerBuffer uTF;
layout(std430, binding = VS_LIGHTMS_SCENE) readonly buffer Params { VsLightSceneParams P; };
layout(binding = VS_LIGHTMS_DIRECT, rgba32f) uniform writeonly image3D uDirect;
layout(binding = VS_LIGHTMS_TRANSMITTANCE, rgba32f) uniform writeonly image3D uTransmittance;
#define VS_TF_ENTRY_TEXELS
#include "volume_access.glsl"

void main()
{
  uvec3 cell = gl_GlobalInvocationID;
  if (any(greaterThanEqual(cell, P.cells)))
    return;
  vs_set_cropping(P.volume.cropLo, P.volume.cropHi, P.volume.cropFlags);
  ivec3 dims = ivec3(P.volume.dims);
  vec3 x = P.volume.boxMin + (vec3(cell) + 0.5) * P.cellSize;
  vec3 xw = (P.indexToWorld * vec4(x, 1.0)).xyz;
  float step = max(P.step, 1e-6);
  vec3 direct = vec3(0.0);
  vec4 group[2] = vec4[2](vec4(1.0), vec4(1.0));
  for (uint l = 0u; l < P.lightCount; ++l)
  {
    vec3 w;
    float distance;
    vec3 E = vs_scene_light_incident(P.lights[l], xw, w, distance);
    vec3 di = (P.volume.worldToIndex * vec4(w, 0.0)).xyz;
    vec2 t = vs_intersect_box(x, di, P.volume.boxMin, P.volume.boxMax);
    t = vs_clip_planes(x, di, t, P.volume.clipPlanes, P.volume.clipPlaneCount);
    t.x = max(t.x, 0.0);
    t.y = min(t.y, distance);
    float depth = 0.0;
    for (float a = t.x; a < t.y; a += step)
    {
      float b = min(a + step, t.y);
      vec3 p = x + (0.5 * (a + b)) * di;
      depth += vs_classify_extinction(vs_sample(p, dims, P.volume.interpolation), P.volume.tf) * (b - a);
    }
    float T = exp(-depth);
    group[l / 4u][l % 4u] = T;
    direct += T * E;
  }
  imageStore(uTransmittance, ivec3(cell), group[0]);
  imageStore(uTransmittance, ivec3(cell.x, cell.y, cell.z + P.cells.z), group[1]);
  imageStore(uDirect, ivec3(cell), vec4(direct, 0.0));
}
