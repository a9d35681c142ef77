#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Sweep-space filtering (von Radziewsky et al. 2017, Sec. 8) along the kernel's axis a, fused with
 * the projection's linear interpolation along a. The projection of step (4) reads the filtered
 * kernel at the point where a cell centre projects along the light onto the start plane; in one
 * slice that point's coordinate along a depends only on the cell's index along a (the cells of a
 * slice form a grid, the light is parallel). So the filter and the interpolation along a are done
 * once per (cell column along a, kernel row along b) of each slice, here, and sweep_project then
 * filters and interpolates these values along b for every cell (separable: the same result as
 * filtering the whole kernel along a, then b, then reading it bilinearly, for fewer reads and no
 * prefix sums). Box width along a: the visibility cell projected onto the sweep plane, widened on
 * each side by t_i tan(beta) (Eq. 9); weights: vs_kernel_taps (sweep_params.h).
 * One invocation per (cell index along a, kernel row) per slice of the chunk per direction.
 */
#include "bindings.h"
#include "sweep_params.h"

/* One row of work per subgroup: the width is the device's subgroup size within [8, 64]
 * (vs::DeviceInfo::RowWorkgroupWidth: 8 on lavapipe, 32 on NVIDIA), constant 1, set by the host. */
layout(local_size_x_id = 1, local_size_y = 1, local_size_z = 1) in;
/* Rays of nonzero weight at most (vs_kernel_taps), for every direction of the dispatch: the tap
 * loops unroll and the weights stay in registers; 0 = any number (a loop). */
layout(constant_id = 0) const int VS_TAPS = 4;
const int VS_TAPS_ARRAY = VS_TAPS > 0 ? VS_TAPS : 1;
layout(std430, binding = VS_FILTER_GLOBALS) readonly buffer Globals { VsSweepParams G; };
layout(std430, binding = VS_FILTER_DIRECTIONS) readonly buffer Directions { VsSweepDirection uDir[]; };
/* r32f texels: lavapipe gathers a texel buffer at per-lane indices in one vector load, a storage
 * buffer in a scalar loop over the lanes. */
layout(binding = VS_FILTER_STACK) uniform samplerBuffer uStack;
layout(std430, binding = VS_FILTER_FILTERED) writeonly buffer Filtered { float uFiltered[]; };
layout(push_constant) uniform Push { uint firstSlice; uint count; uint firstDirection; } pc;

/* One invocation per cell index along a per slice per direction: the weights are the same for
 * every kernel row, so they are computed once and the invocation walks the rows. */
void main()
{
  uint s = gl_GlobalInvocationID.y;
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z];
  uint k = D.axes.x, a = D.axes.y;
  uint slice = pc.firstSlice + s;
  uint ca = gl_GlobalInvocationID.x;
  uint cellsA = G.grid.cells[a];
  uvec2 n = D.kernel.xy;
  if (s >= pc.count || slice >= G.grid.cells[k] || ca >= cellsA)
    return;
  float t = vs_slice_t(G.volume.boxMin[k], G.grid.cellSize[k], G.grid.cells[k], D.planeOrigin[k], D.travel[k], D.kernel.z == 1u, slice);
  float pa = G.volume.boxMin[a] + (float(ca) + 0.5) * G.grid.cellSize[a];
  float u = (pa - t * D.travel[a] - D.planeOrigin[a]) / D.kernelStep.x;
  VsKernelTaps w = vs_kernel_taps(u, n.x, D.filterSize.x + 2.0 * t * D.filterSize.z);
  uint base = D.axes.w * pc.count + s * n.x * n.y;
  uint out0 = D.filtered.x * pc.count + s * cellsA * n.y + ca;
  if (VS_TAPS == 0)
  {
    // Wide boxes: the rays of nonzero weight in a loop, weights recomputed per row.
    float weights = 0.0;
    for (int i = w.first; i <= w.last; ++i)
      weights += vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, i);
    for (uint row = 0u; row < n.y; ++row)
    {
      float sum = 0.0;
      for (int i = w.first; i <= w.last; ++i)
        sum += texelFetch(uStack, int(base + row * n.x + uint(i))).r * vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, i);
      uFiltered[out0 + row * cellsA] = sum / weights;
    }
    return;
  }
  float weight[VS_TAPS_ARRAY];
  uint ray[VS_TAPS_ARRAY];
  float weights = 0.0;
  for (int i = 0; i < VS_TAPS; ++i)
  {
    int j = w.first + i;
    weight[i] = j <= w.last ? vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, j) : 0.0;
    ray[i] = base + uint(min(j, int(n.x) - 1));
    weights += weight[i];
  }
  for (uint row = 0u; row < n.y; ++row)
  {
    float sum = 0.0;
    for (int i = 0; i < VS_TAPS; ++i)
      sum += texelFetch(uStack, int(ray[i] + row * n.x)).r * weight[i];
    // Divided by the weights' sum (1 up to rounding), so that a constant kernel stays exactly constant.
    uFiltered[out0 + row * cellsA] = sum / weights;
  }
}
