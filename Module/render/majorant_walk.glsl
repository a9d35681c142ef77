/*
 * majorant_walk.glsl — the render kernel's majorant segments: one walk for delta and ratio tracking
 * (majorant_segment), brick by brick over the majorant grid (brick_walk.h), across empty space in
 * one step, and cell by cell with a bisected local majorant where a brick is optically thick
 * (refine_majorant). Also the exponential free-flight step. Included once, by mc_render.glsl.
 */

/* Brick b's majorant, control extinction (<= every sample's) and empty-space distance (0, or where
 * the majorant is 0 the chessboard distance in bricks to the nearest brick whose majorant is not:
 * vsEmptySpaceDistance.h); b clamps to the grid. */
vec3 brick_walk_values(ivec3 b)
{
  VS_COUNT(1);
  return imageLoad(uBricks, clamp(b, ivec3(0), gBricks - 1)).xyz;
}

/* The kernel's hot paths are written without constant-length loops: lavapipe's loop limiter counts
 * every back-edge (see the top of this file), and a loop the compiler keeps would cost budget. */

/* The distance along d from p to the face ahead of the voxel cell from lo to lo + 1 on one axis,
 * except the volume's outer faces (of `dim` voxels): scalars clamp beyond them (1e30: none). */
float cell_face_distance(float p, float d, int lo, int dim)
{
  if (d > 1e-20)
    return lo + 1 < dim - 1 ? (float(lo + 1) - p) / d : 1e30;
  if (d < -1e-20)
    return lo > 0 ? (float(lo) - p) / d : 1e30;
  return 1e30;
}

/* Where the ray o + t d leaves the cube of bricks [b - r, b + r] (r >= 0 bricks; r = 0: brick b),
 * at least the shortest step on (brick_walk.h). */
float brick_cube_exit(vec3 o, vec3 d, float t, ivec3 b, float r)
{
  return vs_brick_cube_exit(o, d, gRay.invD, t, vs_walk_min_step(t, gRay.walkScale), b, r, gBrickSize);
}

/* The brick the ray o + t d is in just after t (a brick and a cell are picked at the same point),
 * and the distance t where it leaves it (brick_walk.h). */
ivec3 brick_at(vec3 o, vec3 d, float t, out float tExit)
{
  float h = vs_walk_min_step(t, gRay.walkScale);
  ivec3 b = vs_brick_after(o, d, t, h, gInvBrickSize);
  tExit = vs_brick_cube_exit(o, d, gRay.invD, t, h, b, 0.0, gBrickSize);
  return b;
}

/* The exponential free-flight distance of rate mu for a uniform u in [0,1). */
float sample_exponential(float u, float mu)
{
  return -log(1.0 - u) / mu;
}

/* Trilinear interpolation inside one voxel cell: corners c0 = (000, 100, 010, 110),
 * c1 = (001, 101, 011, 111), local coordinates f in [0,1]^3. */
float cell_trilinear(vec4 c0, vec4 c1, vec3 f)
{
  vec4 z = mix(c0, c1, f.z);
  vec2 y = mix(z.xy, z.zw, f.y);
  return mix(y.x, y.y, f.x);
}

/* The largest extinction on the ray segment [ta, tb] inside the voxel cell `lo`: a trilinear
 * interpolant takes its extremes over a box at the box's corners, so the scalars of the segment lie
 * between the smallest and largest interpolant at the 8 corners of its bounding box. */
float segment_max_extinction(vec3 o, vec3 d, float ta, float tb, ivec3 lo, vec4 c0, vec4 c1)
{
  vec3 top = vec3(gDims - 1);
  vec3 fa = clamp(clamp(o + ta * d, vec3(0.0), top) - vec3(lo), 0.0, 1.0);
  vec3 fb = clamp(clamp(o + tb * d, vec3(0.0), top) - vec3(lo), 0.0, 1.0);
  vec3 f0 = min(fa, fb), f1 = max(fa, fb);
  if (gInterpolation == VS_INTERPOLATION_NEAREST)
    return vs_nearest_max_extinction(f0, f1, c0, c1, gTF); /* the corners whose halves it reaches */
  /* The 8 corners of the box [f0, f1], unrolled. */
  float v0 = cell_trilinear(c0, c1, vec3(f0.x, f0.y, f0.z)), v1 = cell_trilinear(c0, c1, vec3(f1.x, f0.y, f0.z));
  float v2 = cell_trilinear(c0, c1, vec3(f0.x, f1.y, f0.z)), v3 = cell_trilinear(c0, c1, vec3(f1.x, f1.y, f0.z));
  float v4 = cell_trilinear(c0, c1, vec3(f0.x, f0.y, f1.z)), v5 = cell_trilinear(c0, c1, vec3(f1.x, f0.y, f1.z));
  float v6 = cell_trilinear(c0, c1, vec3(f0.x, f1.y, f1.z)), v7 = cell_trilinear(c0, c1, vec3(f1.x, f1.y, f1.z));
  float smin = min(min(min(v0, v1), min(v2, v3)), min(min(v4, v5), min(v6, v7)));
  float smax = max(max(max(v0, v1), max(v2, v3)), max(max(v4, v5), max(v6, v7)));
  return vs_max_extinction(smin, smax, gTF);
}

/* The cell walk's bound with the extinction factor: segment_max_extinction times the largest factor
 * of the cell's corners (refine_majorant sets gCellFactor; both are upper bounds and the float
 * product rounds monotonically, so the product bounds sigma_t(s) x g of every sample). */
float gCellFactor = 1.0;

float segment_majorant(vec3 o, vec3 d, float ta, float tb, ivec3 lo, vec4 c0, vec4 c1)
{
  float m = segment_max_extinction(o, d, ta, tb, lo, c0, c1);
  return VS_SPEC_FACTOR != 0u ? m * gCellFactor : m;
}

/* One step of refine_majorant's bisection in log length, while the bracket is wider than 1%. */
void bisect_step(vec3 o, vec3 d, float t, ivec3 lo, vec4 c0, vec4 c1, inout float hLo, inout float hHi, inout float mLo)
{
  if (!(hHi > 1.01 * hLo))
    return;
  float hMid = sqrt(hLo * hHi);
  float mMid = segment_majorant(o, d, t, t + hMid, lo, c0, c1);
  if (mMid * hMid <= gRefineDepth)
  {
    hLo = hMid;
    mLo = mMid;
  }
  else
    hHi = hMid;
}

/* A brick whose majorant segment is optically thick (mu * length > gRefineDepth: a dense medium, or a
 * tiny unit distance) is walked in voxel cells instead, with the majorant of the sub-segment
 * [t, tNext) of the current cell: the longest sub-segment whose optical depth at its own majorant
 * stays below gRefineDepth (bisection in log length), or the shortest step float resolves. So the
 * trackers take O(optical depth) steps, never O(brick majorant x length): at an extinction of 1e9
 * per voxel the brick majorant would ask for 1e9 null collisions per voxel, at steps float cannot add
 * to t. The segments start where the previous one ended, so the majorant is a fixed function of
 * the ray and the estimators stay unbiased. */
float refine_majorant(vec3 o, vec3 d, float t, inout float tNext, float mu)
{
  float hMin = vs_walk_min_step(t, gRay.walkScale); /* the brick walk's shortest step (brick_walk.h) */
  vec3 p = o + t * d;
  ivec3 lo = clamp(ivec3(floor(o + (t + 0.5 * hMin) * d)), ivec3(0), max(gDims - 2, ivec3(0)));
  ivec3 hi = min(lo + 1, gDims - 1);
  float e = min(cell_face_distance(p.x, d.x, lo.x, gDims.x),
    min(cell_face_distance(p.y, d.y, lo.y, gDims.y), cell_face_distance(p.z, d.z, lo.z, gDims.z)));
  if (gInterpolation == VS_INTERPOLATION_NEAREST)
    e = min(e, vs_nearest_midplane_exit(p, d, lo)); /* segments end where the nearest voxel changes */
  float hMax = min(tNext - t, max(e, hMin));
  vec4 c0, c1;
  kernel_cell_corners(lo, hi, c0, c1);
  VS_COUNT(0);
  if (gInterpolation != VS_INTERPOLATION_NEAREST && (any(isnan(c0)) || any(isnan(c1))))
  {
    /* A NaN corner makes every trilinear sample of the cell NaN: empty space (volume_access.glsl). */
    tNext = t + hMax;
    return 0.0;
  }
  if (VS_SPEC_FACTOR != 0u)
    gCellFactor = vs_cell_max_factor(lo, hi);
  float m = segment_majorant(o, d, t, t + hMax, lo, c0, c1);
  float h = hMax;
  if (m * h > gRefineDepth)
  {
    /* m(h) h grows with h: bisect for the longest h that keeps it below the depth. */
    float hLo = hMin, hHi = hMax;
    float mLo = segment_majorant(o, d, t, t + hLo, lo, c0, c1);
    for (int k = 0; k < 12 && hHi > 1.01 * hLo; ++k)
      bisect_step(o, d, t, lo, c0, c1, hLo, hHi, mLo);
    h = hLo;
    m = mLo;
  }
  tNext = t + h;
  /* The brick majorant bounds the cell too (up to rounding at brick faces). */
  return min(m, mu);
}

/* The majorant segment of the ray from t: returns mu and sets tNext, with mu >= the extinction
 * on [t, tNext). One walk for delta tracking and ratio tracking, without loops. In an empty brick
 * at distance k from the nearest non-empty one, the segment runs to the exit of the cube of
 * (2k - 1)^3 empty bricks around it: one step across empty space instead of one per brick. */
const bool VS_SPEC_SHADOW_CONTROL = (VS_SPEC_CONTROL & VS_CONTROL_SHADOW) != 0u;
const bool VS_SPEC_CAMERA_CONTROL = (VS_SPEC_CONTROL & VS_CONTROL_CAMERA) != 0u;
float gControl; /* majorant_segment's control extinction (VS_SPEC_CONTROL): <= the extinction on the segment */

float majorant_segment(vec3 o, vec3 d, float t, float tEnd, out float tNext)
{
  float tExit;
  ivec3 b = brick_at(o, d, t, tExit);
  vec3 brick = brick_walk_values(b);
  float mu = brick.x;
  if (VS_SPEC_CONTROL != 0u)
    gControl = brick.y;
  if (VS_SPEC_SKIP != 0u && mu == 0.0 && all(greaterThanEqual(b, ivec3(0))) && all(lessThan(b, gBricks)))
  {
    float k = brick.z;
    if (k > 1.0)
      tExit = max(tExit, brick_cube_exit(o, d, t, b, k - 1.0));
  }
  tNext = min(tExit, tEnd);
  if (VS_SPEC_REFINE != 0u && mu * (tNext - t) > gRefineDepth)
    mu = refine_majorant(o, d, t, tNext, mu);
  if (VS_SPEC_CONTROL != 0u)
    gControl = min(gControl, mu);
  return mu;
}
