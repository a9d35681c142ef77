/*
 * Visibility sweep, step (3) of von Radziewsky et al. 2017 Fig. 4 / Eq. 8. Each kernel ray of each
 * direction of the batch advances through the `count` cell slices of this chunk,
 * multiplying its transmittance by each segment's transmittance, and leaves its
 * value at every slice in the kernel stack (what the sweeping kernel holds when
 * the sweep plane reaches that slice). One invocation walks many slices, so a
 * whole sweep is a few dispatches instead of a few per slice.
 * Included by sweep_march.comp (full resolution) and by sweep_march_pooled.comp, with VS_SWEEP_POOLED: it marches the pooled
 * extinction volume (bound as the image uPool, its occupancy as uPoolOccupancy) in pooled coordinates.
 *
 * A ray only marches the slices its segment of the occupied box (G.occupiedMin/Max) overlaps, and
 * stops marching once its transmittance is below G.stopVisibility: the slices before are the value it
 * starts with, the slices after the value it stopped at (an overestimate by less than G.stopVisibility,
 * which the renderer's pdf absorbs: the grid shapes sampling only). Lavapipe runs a loop for a SIMD
 * group of 8 rays until all 8 leave it, so a row of rays stops marching when all its rays have.
 */
#include "bindings.h"
#include "sweep_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#ifdef VS_SWEEP_POOLED
layout(binding = VS_SWEEP_VOLUME, r32f) uniform readonly image3D uPool;
#define VS_TF_TEXELS
layout(binding = VS_SWEEP_TF) uniform samplerBuffer uTF; /* r32f: the table's floats (volume_access.glsl) */
layout(binding = VS_SWEEP_MAJORANT, r32f) uniform readonly image3D uPoolOccupancy;
#else
layout(binding = VS_SWEEP_VOLUME, r32f) uniform readonly image3D uVolume;
#define VS_TF_TEXELS
layout(binding = VS_SWEEP_TF) uniform samplerBuffer uTF; /* r32f: the table's floats (volume_access.glsl) */
layout(binding = VS_SWEEP_MAJORANT, r32f) uniform readonly image3D uMajorant;
layout(binding = VS_SWEEP_FACTOR_IMAGE, r32f) uniform readonly image3D uFactor; /* read only with VS_SWEEP_FACTOR (sweep_access.glsl) */
#define VS_FACTOR_IMAGE
#endif
layout(std430, binding = VS_SWEEP_GLOBALS) readonly buffer Globals { VsSweepParams G; };
layout(std430, binding = VS_SWEEP_DIRECTIONS) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = VS_SWEEP_STATE) buffer State { float uState[]; };  /* V per ray between chunks */
layout(std430, binding = VS_SWEEP_STACK) writeonly buffer Stack { float uStack[]; };
layout(push_constant) uniform Push { uint firstSlice; uint count; uint firstDirection; } pc;

#include "sweep_access.glsl"


void main()
{
  vs_load_sweep_globals();
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z];
  uvec2 r = gl_GlobalInvocationID.xy;
  if (r.x >= D.kernel.x || r.y >= D.kernel.y)
    return;
  uint rays = D.kernel.x * D.kernel.y;
  uint ray = r.y * D.kernel.x + r.x;
  uint k = D.axes.x;
  uint slices = G.grid.cells[k];
  float boxMinK = G.volume.boxMin[k], cellSizeK = G.grid.cellSize[k], startK = D.planeOrigin[k], travelK = D.travel[k];
  bool descending = D.kernel.z == 1u;
  vec3 o = D.planeOrigin.xyz;
  o[D.axes.y] += float(r.x) * D.kernelStep.x;
  o[D.axes.z] += float(r.y) * D.kernelStep.y;
  vec3 d = D.travel.xyz;
  // The part of the ray that can gather optical depth: inside the occupied box and the clip planes.
  vec2 box = vs_intersect_box(o, d, G.occupiedMin, G.occupiedMax);
  vec2 keep = vs_clip_interval(o, d);
  box = vec2(max(box.x, keep.x), min(box.y, keep.y));
#ifdef VS_SWEEP_POOLED
  // The pooled march runs in pooled texels.
  o = (o - vec3(G.poolCentre)) / G.poolVoxels;
  d = d / G.poolVoxels;
#endif
  float stop = G.stopVisibility;
  float V = pc.firstSlice == 0u ? 1.0 : uState[D.axes.w + ray];
  uint end = min(pc.firstSlice + pc.count, slices);
  uint out0 = D.axes.w * pc.count + ray - pc.firstSlice * rays; /* stack index of slice s: out0 + s * rays */
  // Slices whose segment ends before the ray reaches the occupied box keep V (slice t is
  // t(0) + s * dt; one slice of margin against rounding: a marched empty segment adds nothing).
  float tFirst = vs_slice_t(boxMinK, cellSizeK, slices, startK, travelK, descending, 0u);
  float dtSlice = cellSizeK / abs(travelK);
  float ahead = box.x < box.y ? clamp(floor((box.x - tFirst) / dtSlice), 0.0, float(slices)) : float(slices);
  uint enter = clamp(uint(ahead), pc.firstSlice, end);
  uint s = pc.firstSlice;
  for (; s < enter; ++s)
    uStack[out0 + s * rays] = V;
  float t0 = s == 0u ? 0.0 : vs_slice_t(boxMinK, cellSizeK, slices, startK, travelK, descending, s - 1u);
  for (; s < end; ++s)
  {
    if (!(V > stop) || t0 >= box.y)
      break;
    float t1 = vs_slice_t(boxMinK, cellSizeK, slices, startK, travelK, descending, s);
    V *= exp(-vs_optical_depth(o, d, max(t0, box.x), min(t1, box.y)));
    uStack[out0 + s * rays] = V;
    t0 = t1;
  }
  // Past the occupied box, or stopped: V holds for the rest of the chunk (and the next ones).
  for (; s < end; ++s)
    uStack[out0 + s * rays] = V;
  uState[D.axes.w + ray] = V;
}
