/*
 * Visibility sweep, step (3) of von Radziewsky et al. 2017 Fig. 4 / Eq. 8. Each kernel ray of each
 * direction of the batch advances through the `count` cell slices of this chunk,
 * multiplying its transmittance by each segment's transmittance, and leaves its
 * value at every slice in the kernel stack (what the sweeping kernel holds when
 * the sweep plane reaches that slice). One invocation walks many slices, so a
 * whole sweep is a few dispatches instead of a few per slice.
 * Included by sweep_march.comp (full resolution) and by sweep_march_pooled.comp, with VS_SWEEP_POOLED: it marches the pooled
 * extinction volume (bound as uVolume, its occupancy as uMajorant) in pooled coordinates.
 */
#include "sweep_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, r32f) uniform readonly image3D uVolume;
layout(std430, binding = 1) readonly buffer TransferFunction { vec4 uTF[]; };
layout(binding = 2, r32f) uniform readonly image3D uMajorant;
layout(std430, binding = 3) readonly buffer Globals { VsSweepGlobals G; };
layout(std430, binding = 4) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(std430, binding = 5) buffer State { float uState[]; };  /* V per ray between chunks */
layout(std430, binding = 6) writeonly buffer Stack { float uStack[]; };
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
  uint slices = G.grid[k];
  float boxMinK = G.boxMin[k], cellSizeK = G.cellSize[k], startK = D.planeOrigin[k], travelK = D.travel[k];
  bool descending = D.kernel.z == 1u;
  vec3 o = D.planeOrigin.xyz;
  o[D.axes.y] += float(r.x) * D.kernelStep.x;
  o[D.axes.z] += float(r.y) * D.kernelStep.y;
  vec3 d = D.travel.xyz;
  vec2 box = vs_intersect_box(o, d, G.boxMin.xyz, G.boxMax.xyz);
#ifdef VS_SWEEP_POOLED
  // Clip planes cut the ray's interval (exact), the pooled march then runs in pooled texels.
  vec2 keep = vs_clip_interval(o, d);
  box = vec2(max(box.x, keep.x), min(box.y, keep.y));
  o = (o - vec3(G.pool.z)) / G.pool.x;
  d = d / G.pool.x;
#endif
  float V = pc.firstSlice == 0u ? 1.0 : uState[D.axes.w + ray];
  float t0 = pc.firstSlice == 0u ? 0.0
    : vs_slice_t(boxMinK, cellSizeK, slices, startK, travelK, descending, pc.firstSlice - 1u);
  for (uint s = 0u; s < pc.count; ++s)
  {
    uint slice = pc.firstSlice + s;
    if (slice >= slices)
      break;
    float t1 = vs_slice_t(boxMinK, cellSizeK, slices, startK, travelK, descending, slice);
    if (V > G.march.z)
      V *= exp(-vs_optical_depth(o, d, max(t0, box.x), min(t1, box.y)));
    uStack[D.axes.w * pc.count + s * rays + ray] = V;
    t0 = t1;
  }
  uState[D.axes.w + ray] = V;
}
