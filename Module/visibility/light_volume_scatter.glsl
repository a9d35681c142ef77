/*
 * light_volume_scatter.glsl — one order of the light volume's multiple scattering (vsLightVolume.h),
 * deterministic, one invocation per cell. The light arriving at cell c after one more scattering,
 *   I_{k+1}(c) = sum over the D x D grid directions n of (4 pi / D^2) L_n(c),
 *   L_n(c) = int T(c, x) sigma_s(x) I_k(x) / (4 pi) ds   along the ray from c towards n,
 * (isotropic phase: the in-scattered radiance of a point lit by I_k is sigma_s I_k / (4 pi)). The
 * grid already holds what the march needs: V(c, n) is the transmittance from c to the box towards n,
 * so the transmittance from c to a point x upstream on the same ray is V(c, n) / V(x, n), and the
 * opacity of a segment [x_{j-1}, x_j] seen from c, T(c, x_{j-1}) (1 - T(x_{j-1}, x_j)), is
 * t_{j-1} - t_j with t_j = V(c, n) / V(x_j, n): the weights telescope to 1 - V(c, n), the light the
 * environment does not send straight to c. A segment emits a I_k, the albedo and the light of its two
 * ends' cells weighted by their mean extinction sigma (the albedo pass's, light_volume_albedo.comp: a
 * segment from a dense cell into the air scatters as the dense cell does), so
 *   I_{k+1}(c) = (1 / D^2) sum_n sum_j (t_{j-1} - t_j) (E_k(x_{j-1}) + E_k(x_j)) / (s(x_{j-1}) + s(x_j)),
 * E_k = sigma a I_k. Conservation holds exactly: under a constant sky L and albedo 1, I_1 + I_2 + ... =
 * 4 pi L in every cell, whatever V is (the furnace: the volume is then invisible), as long as every
 * segment that attenuates has an end with extinction. t_j is kept non-increasing (the
 * nearest cells' V need not be monotone along the ray), the march steps 1 cell four times, then
 * lengthens by 1.5x up to 8 cells, stops where all but 1e-3 of the weight is spent and gives what is
 * left, t - V(c, n), to the last cell it read (so the weights still sum to 1 - V(c, n)).
 * With P.stride > 1 the order marches one direction of each stride x stride block of texels (the
 * orders take turns over the block's texels, P.offset*), standing for the block: multiply scattered
 * light varies slowly with direction, and the march is stride^2 times cheaper.
 * Writes I_{k+1} into the total (rgb += ; alpha, the mean visibility, untouched), and E_{k+1} and
 * I_{k+1} for the next order (the orders not computed are added on the host: vsLightVolume.cxx).
 * The phase's anisotropy (issue 39; specialization constant 1 >= 1, P.anisotropy = g != 0): the order is carried in
 * the similar medium (sampling/phase_moments.h vs_similar_*): isotropic, sigma_t* = sigma (1 - a g) and
 * a* = a (1 - g) / (1 - a g) per channel, so a segment's transmittance is its real one (from the grid, as
 * above) to the power sigma_t* / sigma of the segment (its ends' extinction-weighted), the weights
 * t*_{j-1} - t*_j, and a segment emits (S(x_{j-1}) + S(x_j)) / (s*(x_{j-1}) + s*(x_j)) towards c. Its source
 * S: for the orders k >= 2 the similar medium's, sigma* a* I_k = (1 - g) sigma a I_k; for the first order's
 * light (k = 1, the order k = 2: specialization constant 1 = 2) the real phase's, all that the first order scatters, sent towards c as
 * Henyey-Greenstein sends the lobe of I_1 and its moment M_1 (uMoment): sigma a 4 pi I_1 f_HG(m.w_n; g rho)
 * (phase_moments.h vs_hg_lobe_light, w_n the world direction from c towards the segment). The order's band-1
 * moment M_{k+1}(c) = (1 / side^2) sum_n L_n(c) w_n is added to the orders' sum (uMomentSum) and written for
 * the tail (uOrderMoment); vsLightVolume.cxx adds them to the light volume's moment, and the preview's last
 * event towards the camera is Henyey-Greenstein's of I and M (vs_hg_lobe_light). Without it (g = 0) the code
 * above, bit for bit.
 * Included by light_volume_scatter_<format>.comp, which defines VS_VIS_FORMAT.
 */
#include "phase_moments.h"
#include "bindings.h"
#include "light_volume_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(constant_id = 0) const uint VS_SPEC_D = 8u;
/* 0: isotropic; 1: the similar medium, the source (1 - g) sigma a I_k; 2: the similar medium, the source the
   first order's lobe (the order k = 2). A constant, not a push constant: lavapipe runs a branch's body under a
   mask whether or not a lane takes it, so the lobe's four reads and three evaluations per step cost the
   orders k >= 3 a third of their time when a push constant chose the source (measured on ch2). */
layout(constant_id = 1) const uint VS_SPEC_SIMILAR = 0u;
layout(binding = VS_LIGHTMS_VISIBILITY, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = VS_LIGHTMS_SOURCES) readonly buffer Sources { uint uSources[]; };
layout(std430, binding = VS_LIGHTMS_STEPS) readonly buffer Steps { vec4 uSteps[]; };
layout(binding = VS_LIGHTMS_ALBEDO, rgba32f) uniform readonly image3D uAlbedo;
layout(binding = VS_LIGHTMS_LIGHT, rgba32f) uniform image3D uLight;
layout(binding = VS_LIGHTMS_EMIT_IN, rgba32f) uniform readonly image3D uEmitIn;
layout(binding = VS_LIGHTMS_EMIT_OUT, rgba32f) uniform writeonly image3D uEmitOut;
layout(binding = VS_LIGHTMS_ORDER_OUT, rgba32f) uniform writeonly image3D uOrderOut;
/* VS_SPEC_SIMILAR: */
layout(binding = VS_LIGHTMS_ORDER_IN, rgba32f) uniform readonly image3D uOrderIn;
layout(binding = VS_LIGHTMS_MOMENT, rgba32f) uniform readonly image3D uMoment;
layout(binding = VS_LIGHTMS_MOMENT_SUM, rgba32f) uniform image3D uMomentSum;
layout(binding = VS_LIGHTMS_ORDER_MOMENT, rgba32f) uniform writeonly image3D uOrderMoment;
layout(push_constant, std430) uniform Push
{
  VsLightScatterParams P;
};

shared vec3 sSteps[256];
shared uint sSources[256];
shared vec3 sDirection[256]; /* VS_SPEC_SIMILAR: w_n */

#define VS_COUNT(i)
#define VS_DIRECTION_SOURCE(n) sSources[n]
#include "visibility_texel.glsl"

/* VS_SPEC_SIMILAR: the source of cell q towards the cell the march started from, in the direction w (from it
 * towards q), of emission e = (sigma a I_k, sigma): the similar medium's (1 - g) sigma a I_k, or for the first
 * order's light Henyey-Greenstein's of I_1 and M_1 (the header above). */
vec3 similar_source(ivec3 q, vec4 e, vec3 w, float g)
{
  if (VS_SPEC_SIMILAR != 2u || !(e.a > 0.0))
    return (1.0 - g) * e.rgb; /* without extinction: 0 */
  vec3 I = imageLoad(uOrderIn, q).rgb;
  int layer = int(P.cellsZ);
  vec3 phased = vs_hg_lobe_light(I, imageLoad(uMoment, q).rgb, imageLoad(uMoment, q + ivec3(0, 0, layer)).rgb,
    imageLoad(uMoment, q + ivec3(0, 0, 2 * layer)).rgb, w, g);
  return vec3(I.x > 0.0 ? e.r * phased.x / I.x : e.r, I.y > 0.0 ? e.g * phased.y / I.y : e.g,
    I.z > 0.0 ? e.b * phased.z / I.z : e.b);
}

void main()
{
  const uint D = VS_SPEC_D;
  const uint DD = D * D;
  for (uint n = gl_LocalInvocationIndex; n < DD; n += 64u)
  {
    sSteps[n] = uSteps[n].xyz;
    sSources[n] = uSources[n];
    if (VS_SPEC_SIMILAR != 0u)
      sDirection[n] = uSteps[DD + n].xyz;
  }
  barrier();

  uvec3 cell = gl_GlobalInvocationID;
  ivec3 cells = ivec3(P.cellsX, P.cellsY, P.cellsZ);
  if (any(greaterThanEqual(ivec3(cell), cells)))
    return;
  vec4 own = imageLoad(uEmitIn, ivec3(cell));
  vec3 sum = vec3(0.0);
  vec3 mx = vec3(0.0), my = vec3(0.0), mz = vec3(0.0); /* VS_SPEC_SIMILAR */
  uint stride = max(P.stride, 1u);
  uint side = D / stride;
  for (uint m = 0u; m < side * side; ++m)
  {
    uint n = (m % side) * stride + P.offsetX + ((m / side) * stride + P.offsetY) * D;
    float v0 = visibility_texel(cell, n, D);
    vec3 s = sSteps[n];
    vec3 acc = vec3(0.0);
    if (VS_SPEC_SIMILAR != 0u)
    {
      /* the similar medium: per channel, its transmittance ts from c, its extinction s* and source S */
      float g = P.anisotropy;
      vec3 w = sDirection[n];
      vec4 ownAlbedo = imageLoad(uAlbedo, ivec3(cell));
      float prevSigma = own.a;
      vec3 prevS = similar_source(ivec3(cell), own, w, g);
      vec3 prevSt = vs_similar_extinction(own.a, ownAlbedo.rgb, g);
      vec3 lastLit = own.a > 0.0 ? prevS / prevSt : vec3(0.0);
      vec3 lastRatio = own.a > 0.0 ? prevSt / own.a : vec3(1.0);
      bool lit = own.a > 0.0;
      float t = 1.0;
      vec3 ts = vec3(1.0), pending = vec3(0.0);
      float along = 1.0, len = 1.0;
      for (uint j = 0u; j < 48u; ++j)
      {
        ivec3 q = ivec3(floor(vec3(cell) + along * s + 0.5));
        if (any(lessThan(q, ivec3(0))) || any(greaterThanEqual(q, cells)))
          break;
        float v = visibility_texel(uvec3(q), n, D);
        float next = min(t, v0 / max(v, 1e-6));
        vec4 e = imageLoad(uEmitIn, q);
        /* a cell without extinction (air) reads nothing more, and a segment between two such keeps the real
           transmittance (ratio 1) */
        vec3 St = e.a > 0.0 ? vs_similar_extinction(e.a, imageLoad(uAlbedo, q).rgb, g) : vec3(0.0);
        vec3 S = similar_source(q, e, w, g);
        float sigma = prevSigma + e.a;
        float T = t > 0.0 ? next / t : 0.0;
        vec3 tsNext = sigma > 0.0 ? ts * vs_similar_transmittance(T, (prevSt + St) / sigma) : ts * T;
        if (sigma > 0.0)
        {
          acc += (ts - tsNext + pending) * (prevS + S) / (prevSt + St);
          pending = vec3(0.0);
        }
        else
          pending += ts - tsNext;
        if (e.a > 0.0)
        {
          lastLit = S / St;
          lastRatio = St / e.a;
          lit = true;
        }
        t = next;
        ts = tsNext;
        prevSigma = e.a;
        prevS = S;
        prevSt = St;
        if (t - v0 <= 1e-3)
          break;
        along += len;
        len = j >= 3u ? min(len * 1.5, 8.0) : 1.0;
      }
      if (lit)
        acc += (max(ts - ts * vs_similar_transmittance(t > 0.0 ? v0 / t : 0.0, lastRatio), vec3(0.0)) + pending) *
          lastLit;
      mx += w.x * acc;
      my += w.y * acc;
      mz += w.z * acc;
      sum += acc;
      continue;
    }
    vec4 previous = own;
    vec3 lastLit = own.a > 0.0 ? own.rgb / own.a : vec3(0.0); /* a I_k of the last cell with extinction */
    bool lit = own.a > 0.0;
    float t = 1.0, pending = 0.0;
    float along = 1.0, len = 1.0;
    acc = vec3(0.0);
    for (uint j = 0u; j < 48u; ++j)
    {
      ivec3 q = ivec3(floor(vec3(cell) + along * s + 0.5));
      if (any(lessThan(q, ivec3(0))) || any(greaterThanEqual(q, cells)))
        break;
      float v = visibility_texel(uvec3(q), n, D);
      float next = min(t, v0 / max(v, 1e-6));
      vec4 e = imageLoad(uEmitIn, q);
      float sigma = previous.a + e.a;
      if (sigma > 0.0)
      {
        /* a segment that attenuates between two cells without extinction (a long step over a thin
           layer) left its weight pending: the next cell with extinction scatters it */
        acc += (t - next + pending) / sigma * (previous.rgb + e.rgb);
        pending = 0.0;
      }
      else
        pending += t - next;
      if (e.a > 0.0)
      {
        lastLit = e.rgb / e.a;
        lit = true;
      }
      t = next;
      previous = e;
      if (t - v0 <= 1e-3)
        break;
      along += len;
      len = j >= 3u ? min(len * 1.5, 8.0) : 1.0;
    }
    /* the rest of the weight, to the box (what the march did not read) and pending: the last cell with
       extinction scatters it */
    if (lit)
      acc += (max(t - v0, 0.0) + pending) * lastLit;
    sum += acc;
  }
  vec3 light = sum / float(side * side);
  vec4 albedo = imageLoad(uAlbedo, ivec3(cell));
  vec4 total = imageLoad(uLight, ivec3(cell));
  imageStore(uLight, ivec3(cell), vec4(total.rgb + light, total.a));
  imageStore(uEmitOut, ivec3(cell), vec4(albedo.a * albedo.rgb * light, albedo.a));
  imageStore(uOrderOut, ivec3(cell), vec4(light, 0.0));
  if (VS_SPEC_SIMILAR != 0u)
  {
    float norm = 1.0 / float(side * side);
    ivec3 layer = ivec3(0, 0, cells.z);
    ivec3 at = ivec3(cell);
    vec3 m[3] = vec3[3](mx * norm, my * norm, mz * norm);
    for (int a = 0; a < 3; ++a)
    {
      ivec3 texel = at + a * layer;
      imageStore(uOrderMoment, texel, vec4(m[a], 0.0));
      vec4 before = VS_SPEC_SIMILAR == 2u ? vec4(0.0) : imageLoad(uMomentSum, texel);
      imageStore(uMomentSum, texel, before + vec4(m[a], 0.0));
    }
  }
}
