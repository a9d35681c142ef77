/*
 * light_volume.glsl — the light volume (vsLightVolume.h): per visibility cell, the environment light
 * that reaches it, I(cell) = sum over the D x D grid directions n of V(cell, n) E_n, with E_n the
 * environment's RGB radiance integrated over direction n's texel (radiance x sr, made on the host).
 * For an isotropic phase function the in-scattered radiance at the cell is sigma_s / (4 pi) I.
 * Alpha: the mean visibility over the sphere (the filter's MeanVisibility). One invocation per cell.
 * Included by light_volume_<format>.comp, which defines VS_VIS_FORMAT.
 */
#include "bindings.h"
#include "light_volume_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
/* D (the grid's directions per side) as a specialization constant: the loop over the directions has
 * a constant trip count (measured on ch2's default grid with lavapipe: 3x faster than a loop to a
 * push-constant D that read the sources from their storage buffer). */
layout(constant_id = 0) const uint VS_SPEC_D = 8u;
layout(binding = VS_LIGHT_VISIBILITY, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = VS_LIGHT_SOURCES) readonly buffer Sources { uint uSources[]; }; /* VisibilityGrid::DirectionSources */
layout(std430, binding = VS_LIGHT_RADIANCE) readonly buffer Radiance { vec4 uRadiance[]; };
layout(binding = VS_LIGHT_OUTPUT, rgba32f) uniform writeonly image3D uLight;
layout(push_constant, std430) uniform Push
{
  VsLightVolumeParams P;
};

/* E_n and the direction sources, the same for every cell: read once per workgroup. */
shared vec3 sRadiance[256];
shared uint sSources[256];

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
  }
  barrier();

  uvec3 cell = gl_GlobalInvocationID;
  if (cell.x >= P.cellsX || cell.y >= P.cellsY || cell.z >= P.cellsZ)
    return;
  vec3 light = vec3(0.0);
  float visible = 0.0;
  for (uint n = 0u; n < DD; ++n)
  {
    float v = visibility_texel(cell, n, D);
    light += v * sRadiance[n];
    visible += v;
  }
  imageStore(uLight, ivec3(cell), vec4(light, visible / float(DD)));
}
