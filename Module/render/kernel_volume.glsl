/*
 * kernel_volume.glsl — what the render kernel reads of the volume: the scalar at a point (from the
 * 8-bit quads, the float image or the nearest voxel, with the cropping test only where there are
 * cropping regions), the extinction factor, and a ray's interval inside the box and the clip planes.
 * Included once, by mc_render.glsl, before majorant_walk.glsl (its cell walk reads the corners here).
 */

float gQuadOffset; /* P.volume.quadZero: the scalar of code 0 in the quads */

/* The 4 scalars of a quad texel: (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1). */
vec4 quad_scalars(uint q)
{
  return vec4(float(q & 0xffu), float((q >> 8u) & 0xffu), float((q >> 16u) & 0xffu), float(q >> 24u)) + gQuadOffset;
}

/* vs_sample_scalar from the quads: the same corners (integers, exact in float) mixed in the same
 * order, so the same float, from 2 texel reads instead of 8. */
float quad_trilinear(vec3 p)
{
  vec3 q = clamp(p, vec3(0.0), vec3(gDims - 1));
  ivec3 i0 = ivec3(floor(q));
  int z1 = min(i0.z + 1, gDims.z - 1);
  vec3 f = q - vec3(i0);
  vec4 a = quad_scalars(imageLoad(uQuads, i0).r);
  vec4 b = quad_scalars(imageLoad(uQuads, ivec3(i0.xy, z1)).r);
  float c00 = mix(a.x, a.y, f.x);
  float c10 = mix(a.z, a.w, f.x);
  float c01 = mix(b.x, b.y, f.x);
  float c11 = mix(b.z, b.w, f.x);
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

/* The scalars at the corners of the voxel cell from lo to hi = min(lo + 1, dims - 1), lo <= dims - 2
 * where the volume has 2 voxels along an axis: c0 = (000, 100, 010, 110), c1 = (001, 101, 011, 111).
 * From the quads, 2 reads (a quad's neighbours clamp as hi does), or 8 of the float image. */
void kernel_cell_corners(ivec3 lo, ivec3 hi, out vec4 c0, out vec4 c1)
{
  if (VS_SPEC_QUADS != 0u)
  {
    c0 = quad_scalars(imageLoad(uQuads, lo).r);
    c1 = quad_scalars(imageLoad(uQuads, ivec3(lo.xy, hi.z)).r);
    return;
  }
  c0 = vec4(imageLoad(uVolume, ivec3(lo.x, lo.y, lo.z)).r, imageLoad(uVolume, ivec3(hi.x, lo.y, lo.z)).r,
    imageLoad(uVolume, ivec3(lo.x, hi.y, lo.z)).r, imageLoad(uVolume, ivec3(hi.x, hi.y, lo.z)).r);
  c1 = vec4(imageLoad(uVolume, ivec3(lo.x, lo.y, hi.z)).r, imageLoad(uVolume, ivec3(hi.x, lo.y, hi.z)).r,
    imageLoad(uVolume, ivec3(lo.x, hi.y, hi.z)).r, imageLoad(uVolume, ivec3(hi.x, hi.y, hi.z)).r);
}

/* The scalar at index-space point p (vs_sample), with the cropping test only in the pipelines that
 * have cropping regions: lavapipe would run it at every step otherwise, whatever the flags. */
float kernel_sample(vec3 p)
{
  if (VS_SPEC_CROPPING != 0u && vs_cropped_out(p))
    return uintBitsToFloat(0x7fc00000u); /* NaN: empty space */
  if (VS_SPEC_INTERPOLATION == VS_INTERPOLATION_NEAREST)
    return vs_sample_nearest(p, gDims);
  return VS_SPEC_QUADS != 0u ? quad_trilinear(p) : vs_sample_scalar(p, gDims);
}

/* The extinction factor at index-space point p (1 without one: the pipelines without gradient
 * opacity read nothing more and compute the same bits, x * 1.0 being x). */
float kernel_factor(vec3 p)
{
  if (VS_SPEC_FACTOR == 0u)
    return 1.0;
  return vs_sample_factor(p, gDims, VS_SPEC_INTERPOLATION);
}

/* The ray interval inside the (cropped) box and the kept side of every clip plane (vs_clip_planes'
 * rule), reading the planes from the parameters in place: passed as an array argument, they were
 * copied into every lane's registers under the lanes' mask at every call (~2,000 instructions per
 * shadow ray on lavapipe, measured in its machine code). */
vec2 ray_interval(vec3 o, vec3 d)
{
  vec2 t = vs_intersect_box(o, d, gBoxMin, gBoxMax);
  for (uint i = 0u; i < gClipCount; ++i)
    t = vs_clip_by_plane(gClipPlanes[i], o, d, t);
  return t;
}
