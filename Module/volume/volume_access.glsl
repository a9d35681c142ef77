/*
 * volume_access.glsl — GLSL-only helpers to read the volume and classify it.
 * The including shader declares, before including this file:
 *   layout(binding = VS_<PASS>_VOLUME, r32f) uniform readonly image3D uVolume;   (bindings.h)
 *   layout(std430, binding = VS_<PASS>_TF) readonly buffer TransferFunction { vec4 uTF[]; };
 * or, with VS_TF_TEXELS defined, the same table as a texel buffer of its floats (r32f texels):
 *   layout(binding = VS_<PASS>_TF) uniform samplerBuffer uTF;
 * or, with VS_TF_ENTRY_TEXELS defined, as a texel buffer of its entries (rgba32f texels: one fetch
 * per entry, for passes that read all four channels);
 * (lavapipe loads an r32f texel buffer at per-lane indices with one vector gather per float, a
 * storage buffer with a scalar loop over the SIMD lanes: the render kernel classifies at every
 * tracking step, and its null-collision tests need only the extinction, one float of four).
 * Non-finite voxels are stored as NaN; any interpolated NaN classifies to zero
 * extinction and zero albedo (NaN/Inf voxels are empty space).
 * With VS_FACTOR_IMAGE defined, the includer also declares the extinction factor per voxel (the
 * gradient opacity, vsDeviceVolume.h), read by vs_sample_factor:
 *   layout(binding = VS_<PASS>_FACTOR, r32f) uniform readonly image3D uFactor;
 */
#include "interpolation.h"
#include "ray_box.glsl"
#include "volume_params.h"

/* Trilinear interpolation of the scalar at continuous index p with 8 imageLoads
 * (measured faster than sampler3D on lavapipe). Indices clamp to the volume. */
float vs_sample_scalar(vec3 p, ivec3 dims)
{
  vec3 q = clamp(p, vec3(0.0), vec3(dims - 1));
  ivec3 i0 = ivec3(floor(q));
  ivec3 i1 = min(i0 + 1, dims - 1);
  vec3 f = q - vec3(i0);
  float c000 = imageLoad(uVolume, ivec3(i0.x, i0.y, i0.z)).r;
  float c100 = imageLoad(uVolume, ivec3(i1.x, i0.y, i0.z)).r;
  float c010 = imageLoad(uVolume, ivec3(i0.x, i1.y, i0.z)).r;
  float c110 = imageLoad(uVolume, ivec3(i1.x, i1.y, i0.z)).r;
  float c001 = imageLoad(uVolume, ivec3(i0.x, i0.y, i1.z)).r;
  float c101 = imageLoad(uVolume, ivec3(i1.x, i0.y, i1.z)).r;
  float c011 = imageLoad(uVolume, ivec3(i0.x, i1.y, i1.z)).r;
  float c111 = imageLoad(uVolume, ivec3(i1.x, i1.y, i1.z)).r;
  float c00 = mix(c000, c100, f.x);
  float c10 = mix(c010, c110, f.x);
  float c01 = mix(c001, c101, f.x);
  float c11 = mix(c011, c111, f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* VTK's cropping regions (vsVolumeGeometry.h CropFlags), set by the includer's main() with
 * vs_set_cropping; flags 0 (the default) = no regions. Points of hidden regions are empty space:
 * vs_sample reads NaN there, which classifies to zero extinction and albedo. */
vec3 gCropLo = vec3(0.0), gCropHi = vec3(0.0);
uint gCropFlags = 0u;

void vs_set_cropping(vec3 lo, vec3 hi, uint flags)
{
  gCropLo = lo;
  gCropHi = hi;
  gCropFlags = flags;
}

/* Whether index-space point p lies in a cropping region whose flag is off. */
bool vs_cropped_out(vec3 p)
{
  if (gCropFlags == 0u)
    return false;
  uvec3 r = uvec3(greaterThanEqual(p, gCropLo)) + uvec3(greaterThanEqual(p, gCropHi));
  return (gCropFlags & (1u << (r.x + 3u * r.y + 9u * r.z))) == 0u;
}

/* The nearest voxel's scalar at continuous index p (voxel i owns [i - 0.5, i + 0.5) per axis, as
 * VTK's nearest interpolation), clamped to the volume: one imageLoad. */
float vs_sample_nearest(vec3 p, ivec3 dims)
{
  vec3 q = clamp(p, vec3(0.0), vec3(dims - 1));
  return imageLoad(uVolume, min(ivec3(floor(q + 0.5)), dims - 1)).r;
}

/* The scalar at p under `interpolation` (interpolation.h: VS_INTERPOLATION_LINEAR or _NEAREST,
 * the vtkVolumeProperty's InterpolationType); NaN in a hidden cropping region. */
float vs_sample(vec3 p, ivec3 dims, uint interpolation)
{
  if (vs_cropped_out(p))
    return uintBitsToFloat(0x7fc00000u); /* NaN: empty space */
  return interpolation == VS_INTERPOLATION_NEAREST ? vs_sample_nearest(p, dims) : vs_sample_scalar(p, dims);
}

/* The gradient of the scalar at index-space point x, in world units (scalar per world unit): central
 * differences of vs_sample one voxel either side per axis, d s / d world = transpose(d index / d world)
 * d s / d index. NaN where a difference reads a hidden cropping region or a non-finite voxel. The
 * emission-absorption pass's Phong shading (ea_render.comp) and the path kernel's surface lobe
 * (surface_scattering.glsl) both take their normal from it. An includer that reads the scalar its own
 * way (the path kernel: from the quads, kernel_volume.glsl) defines VS_GRADIENT_SAMPLE(p) to a
 * function giving vs_sample's float, declared before this file. */
#ifndef VS_GRADIENT_SAMPLE
#define VS_GRADIENT_SAMPLE(p) vs_sample(p, dims, interpolation)
#endif
vec3 vs_world_gradient(vec3 x, ivec3 dims, uint interpolation, mat4 worldToIndex)
{
  vec3 g = 0.5 * vec3(VS_GRADIENT_SAMPLE(x + vec3(1.0, 0.0, 0.0)) - VS_GRADIENT_SAMPLE(x - vec3(1.0, 0.0, 0.0)),
                      VS_GRADIENT_SAMPLE(x + vec3(0.0, 1.0, 0.0)) - VS_GRADIENT_SAMPLE(x - vec3(0.0, 1.0, 0.0)),
                      VS_GRADIENT_SAMPLE(x + vec3(0.0, 0.0, 1.0)) - VS_GRADIENT_SAMPLE(x - vec3(0.0, 0.0, 1.0)));
  return transpose(mat3(worldToIndex)) * g;
}

#ifdef VS_FACTOR_IMAGE
/* The extinction factor at continuous index p, interpolated as the scalar is (vs_sample_scalar's
 * trilinear weights, or the nearest voxel), clamped to the volume. */
float vs_sample_factor(vec3 p, ivec3 dims, uint interpolation)
{
  vec3 q = clamp(p, vec3(0.0), vec3(dims - 1));
  if (interpolation == VS_INTERPOLATION_NEAREST)
    return imageLoad(uFactor, min(ivec3(floor(q + 0.5)), dims - 1)).r;
  ivec3 i0 = ivec3(floor(q));
  ivec3 i1 = min(i0 + 1, dims - 1);
  vec3 f = q - vec3(i0);
  float c00 = mix(imageLoad(uFactor, ivec3(i0.x, i0.y, i0.z)).r, imageLoad(uFactor, ivec3(i1.x, i0.y, i0.z)).r, f.x);
  float c10 = mix(imageLoad(uFactor, ivec3(i0.x, i1.y, i0.z)).r, imageLoad(uFactor, ivec3(i1.x, i1.y, i0.z)).r, f.x);
  float c01 = mix(imageLoad(uFactor, ivec3(i0.x, i0.y, i1.z)).r, imageLoad(uFactor, ivec3(i1.x, i0.y, i1.z)).r, f.x);
  float c11 = mix(imageLoad(uFactor, ivec3(i0.x, i1.y, i1.z)).r, imageLoad(uFactor, ivec3(i1.x, i1.y, i1.z)).r, f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* The largest factor a sample in the voxel cell from lo to hi (corners) can read: the largest
 * corner (a trilinear interpolant lies between its corners, a nearest sample reads one), widened
 * by 1e-6 for the rounding of the interpolation (as the bricks' bounds, vsMajorantGrid.h). */
float vs_cell_max_factor(ivec3 lo, ivec3 hi)
{
  float m = max(max(max(imageLoad(uFactor, ivec3(lo.x, lo.y, lo.z)).r, imageLoad(uFactor, ivec3(hi.x, lo.y, lo.z)).r),
                  max(imageLoad(uFactor, ivec3(lo.x, hi.y, lo.z)).r, imageLoad(uFactor, ivec3(hi.x, hi.y, lo.z)).r)),
    max(max(imageLoad(uFactor, ivec3(lo.x, lo.y, hi.z)).r, imageLoad(uFactor, ivec3(hi.x, lo.y, hi.z)).r),
      max(imageLoad(uFactor, ivec3(lo.x, hi.y, hi.z)).r, imageLoad(uFactor, ivec3(hi.x, hi.y, hi.z)).r)));
  return m * (1.0 + 1e-6);
}
#endif

/* Float f of the transfer-function table (entry f / 4, channel f % 4; the range-max levels follow). */
float vs_tf_float(int f)
{
#if defined(VS_TF_ENTRY_TEXELS)
  return texelFetch(uTF, f >> 2)[f & 3];
#elif defined(VS_TF_TEXELS)
  return texelFetch(uTF, f).r;
#else
  return uTF[f >> 2][f & 3];
#endif
}

/* Entry i of the transfer-function table: (albedo rgb, extinction). */
vec4 vs_tf_entry(int i)
{
#if defined(VS_TF_ENTRY_TEXELS)
  return texelFetch(uTF, i);
#elif defined(VS_TF_TEXELS)
  return vec4(vs_tf_float(4 * i), vs_tf_float(4 * i + 1), vs_tf_float(4 * i + 2), vs_tf_float(4 * i + 3));
#else
  return uTF[i];
#endif
}

/* Post-classification: (albedo rgb, extinction per world unit) of scalar s,
 * linear between LUT entries, clamped at the ends as VTK's transfer functions are. */
vec4 vs_classify(float s, VsTransferFunction tf)
{
  if (isnan(s))
    return vec4(0.0);
  float x = clamp((s - tf.scalar0) * tf.entriesPerUnit, 0.0, tf.entries - 1.0);
  int i0 = int(floor(x));
  int i1 = min(i0 + 1, int(tf.entries) - 1);
  return mix(vs_tf_entry(i0), vs_tf_entry(i1), x - float(i0));
}

/* The extinction of scalar s alone: vs_classify(s, tf).w, bit for bit, reading 2 of its 8 floats. */
float vs_classify_extinction(float s, VsTransferFunction tf)
{
  if (isnan(s))
    return 0.0;
  float x = clamp((s - tf.scalar0) * tf.entriesPerUnit, 0.0, tf.entries - 1.0);
  int i0 = int(floor(x));
  int i1 = min(i0 + 1, int(tf.entries) - 1);
  return mix(vs_tf_float(4 * i0 + 3), vs_tf_float(4 * i1 + 3), x - float(i0));
}

/* Extinction entry i of level k of the range-maximum table (vsTransferFunctionTable.h): level 0 is
 * the LUT's w, levels 1.. follow the LUT, 4 floats per vec4. */
float vs_tf_level_max(int level, int i, VsTransferFunction tf)
{
  if (level == 0)
    return vs_tf_float(4 * i + 3);
  int n = int(tf.entries);
  int f = 4 * n + (level - 1) * n + i;
  return vs_tf_float(f);
}

/* The largest extinction vs_classify gives any scalar in [s0, s1], s0 <= s1: two reads of the
 * range-max table, whose tf.rangeLevels levels cover every range of the LUT. The range is widened by 1e-6 of
 * its magnitude, so that the rounding of a sample's scalar inside it (a few ulps) cannot reach an
 * entry outside it; a range of one exact value (an empty cell's zeros) stays exact. */
float vs_max_extinction(float s0, float s1, VsTransferFunction tf)
{
  float widen = 1e-6 * max(abs(s0), abs(s1));
  float last = tf.entries - 1.0;
  float a = clamp((s0 - widen - tf.scalar0) * tf.entriesPerUnit, 0.0, last);
  float b = clamp((s1 + widen - tf.scalar0) * tf.entriesPerUnit, 0.0, last);
  int i = int(floor(a));
  int j = int(ceil(b));
  int k = findMSB(j - i + 1);
  return max(vs_tf_level_max(k, i, tf), vs_tf_level_max(k, j - (1 << k) + 1, tf));
}

/* Under nearest interpolation the cell walk's segments end where the nearest voxel changes: the
 * distance along d from p to the next midplane (lo + 0.5) of the voxel cell lo ahead, 1e30 if none.
 * A midplane within VS_NEAREST_TOLERANCE of p is behind it (p is on it: the previous segment ended
 * there), so a segment never starts with a sliver across it. */
const float VS_NEAREST_TOLERANCE = 1e-4; /* voxels: above the rounding of positions o + t d */

float vs_nearest_midplane_distance(float p, float d, int lo)
{
  float m = float(lo) + 0.5;
  if (d > 1e-20 && p < m - VS_NEAREST_TOLERANCE)
    return (m - p) / d;
  if (d < -1e-20 && p > m + VS_NEAREST_TOLERANCE)
    return (m - p) / d;
  return 1e30;
}

/* Unrolled (lavapipe's loop limiter counts every back-edge of the render kernel). */
float vs_nearest_midplane_exit(vec3 p, vec3 d, ivec3 lo)
{
  return min(vs_nearest_midplane_distance(p.x, d.x, lo.x),
    min(vs_nearest_midplane_distance(p.y, d.y, lo.y), vs_nearest_midplane_distance(p.z, d.z, lo.z)));
}

/* The largest extinction nearest-neighbour samples take on a segment inside the voxel cell whose
 * corners are c0 = (000, 100, 010, 110), c1 = (001, 101, 011, 111) and whose local coordinates
 * (in [0,1]^3) span the box [f0, f1]: a sample reads the corner it is nearest to, so only the
 * corners whose half of the cell the segment's interior reaches along every axis can be read, and
 * the result is the largest of their own classified extinctions (exactly what those samples
 * compute; a NaN corner classifies to 0 and leaves its neighbours' halves as they are). The walk
 * ends segments on the midplanes (vs_nearest_midplane_exit), so a segment reaches a half when it
 * extends more than VS_NEAREST_TOLERANCE into it; one that lies within the tolerance of a midplane
 * reaches both halves. This keeps the majorant tight: a half the segment only touches by the
 * rounding of its end would cost null collisions at its extinction along the whole segment (at an
 * extinction of 1e9 per voxel, tens of thousands per segment; lavapipe ends loops of 65535
 * iterations). A sample whose position rounds across a midplane (a few ulps) may read the voxel
 * beyond it: delta tracking then accepts it, a bias at the resolution of float positions. */
float vs_nearest_max_extinction(vec3 f0, vec3 f1, vec4 c0, vec4 c1, VsTransferFunction tf)
{
  bvec3 low = lessThan(f0, vec3(0.5 - VS_NEAREST_TOLERANCE));
  bvec3 high = greaterThan(f1, vec3(0.5 + VS_NEAREST_TOLERANCE));
  bvec3 neither = not(bvec3(uvec3(low) | uvec3(high))); /* within the tolerance of the midplane: either voxel */
  low = bvec3(uvec3(low) | uvec3(neither));
  high = bvec3(uvec3(high) | uvec3(neither));
  /* The 8 corners, unrolled (lavapipe's loop limiter counts every back-edge of the render kernel). */
  vec4 e0 = vec4(vs_classify_extinction(c0.x, tf), vs_classify_extinction(c0.y, tf), vs_classify_extinction(c0.z, tf),
    vs_classify_extinction(c0.w, tf));
  vec4 e1 = vec4(vs_classify_extinction(c1.x, tf), vs_classify_extinction(c1.y, tf), vs_classify_extinction(c1.z, tf),
    vs_classify_extinction(c1.w, tf));
  /* Corner (x, y) of a z layer is read when its half is reached along x and y. */
  vec4 xy = vec4(low.x && low.y, high.x && low.y, low.x && high.y, high.x && high.y);
  vec4 m = max(e0 * xy * float(low.z), e1 * xy * float(high.z));
  return max(max(m.x, m.y), max(m.z, m.w));
}

/* Clip the interval [t0,t1] of world ray o + t d against the half-spaces kept by the planes. */
vec2 vs_clip_planes(vec3 o, vec3 d, vec2 t, vec4 planes[VS_MAX_CLIP_PLANES], uint count)
{
  for (uint i = 0u; i < count; ++i)
    t = vs_clip_by_plane(planes[i], o, d, t);
  return t;
}
