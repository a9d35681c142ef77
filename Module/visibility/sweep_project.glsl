/*
 * Visibility sweep, step (4) of von Radziewsky et al. 2017 Fig. 4: project the cell centres of each
 * slice of the chunk along the light onto the start plane and read that slice's filtered kernel
 * there; store into the visibility grid, an image of (cells.x * D, cells.y * D, cells.z) texels:
 * cell c holds its D x D directions as a tile. sweep_filter.comp has filtered and interpolated
 * the kernel along a already (one value per cell index along a and kernel row along b); this
 * filters and interpolates those along b (vs_kernel_taps), which completes the separable filter
 * and the bilinear read.
 * Included by sweep_project_{r8,r16,r32f}.comp, which define VS_VIS_FORMAT: a store to an
 * image of known format (on lavapipe, measured no faster than a format-less store; kept so
 * the sweeps do not need shaderStorageImageWriteWithoutFormat for the grid).
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
layout(std430, binding = VS_PROJECT_GLOBALS) readonly buffer Globals { VsSweepParams G; };
layout(std430, binding = VS_PROJECT_DIRECTIONS) readonly buffer Directions { VsSweepDirection uDir[]; };
layout(binding = VS_PROJECT_FILTERED) uniform samplerBuffer uFiltered; /* r32f texels: gathered, as sweep_filter.comp's uStack */
layout(binding = VS_PROJECT_VISIBILITY, VS_VIS_FORMAT) uniform writeonly image3D uVisibility;
layout(push_constant) uniform Push { uint firstSlice; uint count; uint firstDirection; } pc;

/* One invocation per cell row along a (cell index along b, slice) of one direction: the slice's
 * weights along b are the same for every cell of the row, so they are computed once. */
void main()
{
  VsSweepDirection D = uDir[pc.firstDirection + gl_GlobalInvocationID.z];
  uint k = D.axes.x, a = D.axes.y, b = D.axes.z;
  uint cb = gl_GlobalInvocationID.x, s = gl_GlobalInvocationID.y;
  uint slice = pc.firstSlice + s;
  uint cellsK = G.grid.cells[k], cellsA = G.grid.cells[a];
  if (cb >= G.grid.cells[b] || s >= pc.count || slice >= cellsK)
    return;
  uint nb = D.kernel.y;
  uint dir = D.kernel.w;
  uint side = G.grid.side;
  bool descending = D.kernel.z == 1u;
  float t = vs_slice_t(G.volume.boxMin[k], G.grid.cellSize[k], cellsK, D.planeOrigin[k], D.travel[k], descending, slice);
  float pb = G.volume.boxMin[b] + (float(cb) + 0.5) * G.grid.cellSize[b];
  float v = (pb - t * D.travel[b] - D.planeOrigin[b]) / D.kernelStep.y;
  VsKernelTaps w = vs_kernel_taps(v, nb, D.filterSize.y + 2.0 * t * D.filterSize.w);
  uint at = D.filtered.x * pc.count + s * cellsA * nb;
  // The texel of cell index ca along a: first + ca * step.
  uvec3 cell;
  cell[a] = 0u;
  cell[b] = cb;
  cell[k] = descending ? cellsK - 1u - slice : slice;
  ivec3 first = ivec3(int(cell.x * side + dir % side), int(cell.y * side + dir / side), int(cell.z));
  ivec3 step = ivec3(0);
  step[a] = a == 2u ? 1 : int(side);
  if (VS_TAPS == 0)
  {
    // Wide boxes: the rays of nonzero weight in a loop, weights recomputed per cell.
    float weights = 0.0;
    for (int j = w.first; j <= w.last; ++j)
      weights += vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, j);
    for (uint ca = 0u; ca < cellsA; ++ca)
    {
      float V = 0.0;
      for (int j = w.first; j <= w.last; ++j)
        V += texelFetch(uFiltered, int(at + uint(j) * cellsA + ca)).r * vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, j);
      imageStore(uVisibility, first + int(ca) * step, vec4(clamp(V / weights, 0.0, 1.0)));
    }
    return;
  }
  float weight[VS_TAPS_ARRAY];
  uint row[VS_TAPS_ARRAY];
  float weights = 0.0;
  for (int i = 0; i < VS_TAPS; ++i)
  {
    int j = w.first + i;
    weight[i] = j <= w.last ? vs_kernel_tap_weight(w.lo0, w.hi0, w.inv0, w.lo1, w.hi1, w.inv1, w.f, j) : 0.0;
    row[i] = at + uint(min(j, int(nb) - 1)) * cellsA;
    weights += weight[i];
  }
  for (uint ca = 0u; ca < cellsA; ++ca)
  {
    float V = 0.0;
    for (int i = 0; i < VS_TAPS; ++i)
      V += texelFetch(uFiltered, int(row[i] + ca)).r * weight[i];
    // Divided by the weights' sum (1 up to rounding), so that a constant kernel stays exactly constant.
    imageStore(uVisibility, first + int(ca) * step, vec4(clamp(V / weights, 0.0, 1.0)));
  }
}
