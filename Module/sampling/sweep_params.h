/*
 * sweep_params.h — the parameters of the visibility sweeps (von Radziewsky et al. 2017, Sec. 6, 8),
 * shared by the compute shaders and the host (std430, the layout rule of volume_params.h).
 *
 * Index space: continuous voxel coordinates (voxel centres at integers). Visibility
 * V(x, w) is the transmittance from x towards the light direction w (to the box exit).
 * Light travels along -w; in index space its direction per world unit is
 * d = worldToIndex_linear(-w), so parameter t along a kernel ray is a world distance.
 */
#ifndef VS_SWEEP_PARAMS_H
#define VS_SWEEP_PARAMS_H
#include "grid_params.h"
#include "volume_params.h"

VS_NAMESPACE_BEGIN

/* One sweep direction (one texel of the D x D equal-area octahedral map). */
struct VsSweepDirection
{
  vec4 travel;      /* xyz: d, light travel per world unit in index space */
  vec4 planeOrigin; /* xyz: index-space position of kernel ray (0,0) on the start plane */
  vec4 kernelStep;  /* x: index units between kernel rays along axis a, y: along axis b */
  vec4 filterSize;  /* x, y: base box width (kernel texels) along a, b; z, w: widening per world unit along a, b */
  uvec4 axes;       /* x: sweep axis k, y: in-plane axis a, z: in-plane axis b, w: first ray of this direction in its
                       batch (kernel state index; its kernel stack starts at w * slices per chunk) */
  uvec4 kernel;     /* x: rays along a, y: rays along b, z: 1 if slices go from high to low k, w: direction index */
  uvec4 filtered;   /* x: first entry of this direction's kernel filtered along a (cells along a x rays along b
                       per slice) in its batch; its values start at x * slices per chunk. y, z, w: unused */
};

/* What every sweep, filter, projection and brute-force dispatch shares. */
struct VsSweepParams
{
  VsVolumeParams volume; /* the brute force turns world directions into index space by volume.worldToIndex */
  VsGridParams grid;
  float step;           /* march step (world units) */
  float stopVisibility; /* a kernel ray stops when its visibility falls below this */
  uint supersamples;    /* the brute force: spatial x angular supersamples per side (1 = centre only) */
  uint seed;            /* the brute force's random stream */
  /* The pooled extinction volume the sweeps march (sweep_march_pooled.comp): texel j holds the mean
   * (or max) of sigma_t over voxels [j P, j P + P - 1], so its centre is at index j P + (P - 1) / 2. */
  float poolVoxels;     /* voxels per pooled texel P */
  float poolBrickSize;  /* pooled occupancy brick size (texels) */
  float poolCentre;     /* (P - 1) / 2 */
  float poolStep;       /* march step over the pooled volume (world units) */
  uvec3 poolDims;       /* pooled texels per axis */
  uint unused0;
  uvec3 poolBricks;     /* pooled occupancy bricks per axis */
  uint unused1;
  /* Index-space box holding every voxel of nonzero extinction, widened by the pooled texels'
   * reach (conservative: the bricks of nonzero majorant): outside it a kernel ray gathers no
   * optical depth, so the march starts and ends there instead of at the volume's box. */
  vec3 occupiedMin;
  float unused2;
  vec3 occupiedMax;
  float unused3;
};

/* Distance along the light (world units) from the start plane to the centre plane of
 * cell slice `slice` (in processing order); slices are evenly spaced, so this is
 * t0 + slice * dt. Takes scalars, not the structs: a GLSL struct argument is a copy. */
VS_FUNC float vs_slice_t(float boxMinK, float cellSizeK, uint cellsK, float startK, float travelK, bool descending,
  uint slice)
{
  uint c = descending ? cellsK - 1u - slice : slice;
  float coordinate = boxMinK + (float(c) + 0.5f) * cellSizeK;
  return (coordinate - startK) / travelK;
}

/* The sweep-space filter (Sec. 8) and the projection's linear interpolation along one kernel axis,
 * as one set of weights on the kernel's texels. Kernel ray i sits at coordinate i; the filtered
 * kernel at ray c is the mean of the piecewise-constant line (ray i covering [i - 0.5, i + 0.5))
 * over the box of `width` rays centred on c, cut to the line ([-0.5, n - 0.5]) and renormalised;
 * a width below one ray is no filtering (the box of ray c alone). The projection reads the
 * filtered kernel linearly at coordinate u between rays c0 = floor(u) and c0 + 1, clamped to the
 * line. So ray i's weight is (1 - f) |[i, i + 1) n B0| / |B0| + f |[i, i + 1) n B1| / |B1|, in
 * coordinates shifted by one half (ray i covering [i, i + 1)), for the boxes B0, B1 around c0, c1,
 * and only rays first..last have any. One pass reads what the old separate filter passes (prefix
 * sums and differences of their interpolant, per ray) and the bilinear read computed. */
struct VsKernelTaps
{
  float f;              /* the linear weight of c1 */
  float lo0, hi0, inv0; /* B0 = [lo0, hi0] (shifted coordinates), inv0 = 1 / |B0| */
  float lo1, hi1, inv1;
  int first, last;      /* the rays of nonzero weight */
};

VS_FUNC VsKernelTaps vs_kernel_taps(float u, uint n, float width)
{
  VsKernelTaps w;
  float halfWidth = 0.5f * max(width, 1.0f);
  float x0 = floor(u);
  w.f = u - x0;
  float last = float(n) - 1.0f;
  float c0 = clamp(x0, 0.0f, last), c1 = clamp(x0 + 1.0f, 0.0f, last);
  w.lo0 = max(c0 + 0.5f - halfWidth, 0.0f);
  w.hi0 = min(c0 + 0.5f + halfWidth, float(n));
  w.lo1 = max(c1 + 0.5f - halfWidth, 0.0f);
  w.hi1 = min(c1 + 0.5f + halfWidth, float(n));
  w.inv0 = 1.0f / (w.hi0 - w.lo0);
  w.inv1 = 1.0f / (w.hi1 - w.lo1);
  w.first = int(floor(w.lo0));
  w.last = min(int(ceil(w.hi1)), int(n)) - 1;
  return w;
}

/* The weight of ray i (first <= i <= last) under vs_kernel_taps' w. */
VS_FUNC float vs_kernel_tap_weight(float lo0, float hi0, float inv0, float lo1, float hi1, float inv1, float f, int i)
{
  float a = float(i), b = a + 1.0f;
  float o0 = max(min(b, hi0) - max(a, lo0), 0.0f);
  float o1 = max(min(b, hi1) - max(a, lo1), 0.0f);
  return (1.0f - f) * o0 * inv0 + f * o1 * inv1;
}

VS_NAMESPACE_END

#endif
