#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Brute-force visibility: for every cell and direction, ray-march from the cell
 * towards the light to the box exit. With G.supersamples = N > 1, the average of N
 * rays from random points of the cell towards random directions of the direction's
 * octahedral texel — what a visibility cell means. The reference for the sweeps.
 */
#include "bindings.h"
#include "sweep_params.h"
#include "octahedral.h"
#include "rng.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(binding = VS_BRUTE_VOLUME, r32f) uniform readonly image3D uVolume;
#define VS_TF_TEXELS
layout(binding = VS_BRUTE_TF) uniform samplerBuffer uTF; /* r32f: the table's floats (volume_access.glsl) */
layout(binding = VS_BRUTE_MAJORANT, r32f) uniform readonly image3D uMajorant;
layout(std430, binding = VS_BRUTE_GLOBALS) readonly buffer Globals { VsSweepParams G; };
layout(binding = VS_BRUTE_VISIBILITY) uniform writeonly image3D uVisibility;
layout(binding = VS_BRUTE_FACTOR_IMAGE, r32f) uniform readonly image3D uFactor; /* read only with VS_SWEEP_FACTOR (sweep_access.glsl) */
#define VS_FACTOR_IMAGE
layout(push_constant) uniform Push { uint firstCell; uint firstDirection; } pc;

#include "sweep_access.glsl"

void main()
{
  vs_load_sweep_globals();
  uint cellIndex = pc.firstCell + gl_GlobalInvocationID.x;
  uint dir = pc.firstDirection + gl_GlobalInvocationID.y;
  uint cellCount = G.grid.cells.x * G.grid.cells.y * G.grid.cells.z;
  uint side = G.grid.side;
  if (cellIndex >= cellCount || dir >= side * side)
    return;
  uvec3 cell = uvec3(cellIndex % G.grid.cells.x, (cellIndex / G.grid.cells.x) % G.grid.cells.y, cellIndex / (G.grid.cells.x * G.grid.cells.y));
  uvec2 texel = uvec2(dir % side, dir / side);
  uint N = max(G.supersamples, 1u);
  VsRng rng = vs_rng_init(uvec2(cellIndex, dir), 0u, G.seed);
  float sum = 0.0;
  for (uint s = 0u; s < N; ++s)
  {
    vec3 jitter = vec3(0.5);
    vec2 uvJitter = vec2(0.5);
    if (N > 1u)
    {
      jitter = vec3(vs_rng_vec2(rng), vs_rng_float(rng));
      uvJitter = vs_rng_vec2(rng);
    }
    vec3 p = G.volume.boxMin + (vec3(cell) + jitter) * G.grid.cellSize;
    vec3 w = vs_octa_to_dir((vec2(texel) + uvJitter) / float(side));
    vec3 d = (G.volume.worldToIndex * vec4(w, 0.0)).xyz; /* towards the light, per world unit */
    vec2 box = vs_intersect_box(p, d, G.volume.boxMin, G.volume.boxMax);
    sum += exp(-vs_optical_depth(p, d, max(box.x, 0.0), box.y));
  }
  ivec3 t = ivec3(int(cell.x * side + texel.x), int(cell.y * side + texel.y), int(cell.z));
  imageStore(uVisibility, t, vec4(sum / float(N)));
}
