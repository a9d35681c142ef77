/*
 * light_volume.glsl — the light volume (vsLightVolume.h): per visibility cell, the environment light
 * that reaches it, I(cell) = sum over the D x D grid directions n of V(cell, n) E_n, with E_n the
 * environment's RGB radiance integrated over direction n's texel (radiance x sr, made on the host).
 * For an isotropic phase function the in-scattered radiance at the cell is sigma_s / (4 pi) I.
 * Alpha: the mean visibility over the sphere (the filter's MeanVisibility). One invocation per cell.
 * With VS_SPEC_MOMENT (issue 39: the preview's Henyey-Greenstein phase towards the environment) also the
 * band-1 moment M = sum_n V(cell, n) E_n w_n, w_n the world direction towards texel n's light: layer a
 * (z + a cells.z) of uMoment holds M's component a, rgb per channel (sampling/phase_moments.h). With
 * VS_SPEC_MOMENT 2 (the orders >= 2 follow g < 0, vsLightVolume.h) layers 3 .. 5 keep the first order apart: M's
 * component a in rgb and I's channel a in alpha (the scatter passes add the other orders to layers 0 .. 2).
 * Included by light_volume_<format>.comp, which defines VS_VIS_FORMAT.
 */
#include "bindings.h"
#include "light_volume_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
/* D (the grid's directions per side) as a specialization constant: the loop over the directions has
 * a constant trip count (measured on ch2's default grid with lavapipe: 3x faster than a loop to a
 * push-constant D that read the sources from their storage buffer). */
layout(constant_id = 0) const uint VS_SPEC_D = 8u;
layout(constant_id = 1) const uint VS_SPEC_MOMENT = 0u;
layout(binding = VS_LIGHT_VISIBILITY, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = VS_LIGHT_SOURCES) readonly buffer Sources { uint uSources[]; }; /* VisibilityGrid::DirectionSources */
layout(std430, binding = VS_LIGHT_RADIANCE) readonly buffer Radiance { vec4 uRadiance[]; };
layout(binding = VS_LIGHT_OUTPUT, rgba32f) uniform writeonly image3D uLight;
layout(binding = VS_LIGHT_MOMENT, rgba32f) uniform writeonly image3D uMoment; /* written with VS_SPEC_MOMENT */
layout(push_constant, std430) uniform Push
{
  VsLightVolumeParams P;
};

/* E_n and the direction sources, the same for every cell: read once per workgroup. */
shared vec3 sRadiance[256];
shared uint sSources[256];
shared vec3 sDirection[256]; /* VS_SPEC_MOMENT */

#define VS_COUNT(i)
#define VS_DIRECTION_SOURCE(n) sSources[n]
#include "visibility_texel.glsl"

void main()
{
  const uint D = VS_SPEC_D;
  const uint DD = D * D;
  for (uint n = gl_LocalInvocationIndex; n < DD; n += 64u)
  {
    sRadiance[n] = uRadiance[n].rgb;
    sSources[n] = uSources[n];
    if (VS_SPEC_MOMENT != 0u)
      sDirection[n] = uRadiance[DD + n].xyz;
  }
  barrier();

  uvec3 cell = gl_GlobalInvocationID;
  if (cell.x >= P.cellsX || cell.y >= P.cellsY || cell.z >= P.cellsZ)
    return;
  vec3 light = vec3(0.0);
  float visible = 0.0;
  vec3 mx = vec3(0.0), my = vec3(0.0), mz = vec3(0.0);
  for (uint n = 0u; n < DD; ++n)
  {
    float v = visibility_texel(cell, n, D);
    vec3 e = v * sRadiance[n];
    light += e;
    visible += v;
    if (VS_SPEC_MOMENT != 0u)
    {
      vec3 w = sDirection[n];
      mx += w.x * e;
      my += w.y * e;
      mz += w.z * e;
    }
  }
  imageStore(uLight, ivec3(cell), vec4(light, visible / float(DD)));
  if (VS_SPEC_MOMENT != 0u)
  {
    int layer = int(P.cellsZ);
    imageStore(uMoment, ivec3(cell), vec4(mx, 0.0));
    imageStore(uMoment, ivec3(cell) + ivec3(0, 0, layer), vec4(my, 0.0));
    imageStore(uMoment, ivec3(cell) + ivec3(0, 0, 2 * layer), vec4(mz, 0.0));
    if (VS_SPEC_MOMENT == 2u)
    {
      /* the first order kept apart (the orders >= 2 are added to layers 0 .. 2): M_1 and I_1 per component */
      imageStore(uMoment, ivec3(cell) + ivec3(0, 0, 3 * layer), vec4(mx, light.x));
      imageStore(uMoment, ivec3(cell) + ivec3(0, 0, 4 * layer), vec4(my, light.y));
      imageStore(uMoment, ivec3(cell) + ivec3(0, 0, 5 * layer), vec4(mz, light.z));
    }
  }
}
