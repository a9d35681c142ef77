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
 * Included by light_volume_scatter_<format>.comp, which defines VS_VIS_FORMAT.
 */
#include "bindings.h"
#include "light_volume_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(constant_id = 0) const uint VS_SPEC_D = 8u;
layout(binding = VS_LIGHTMS_VISIBILITY, VS_VIS_FORMAT) uniform readonly image3D uVisibility;
layout(std430, binding = VS_LIGHTMS_SOURCES) readonly buffer Sources { uint uSources[]; };
layout(std430, binding = VS_LIGHTMS_STEPS) readonly buffer Steps { vec4 uSteps[]; };
layout(binding = VS_LIGHTMS_ALBEDO, rgba32f) uniform readonly image3D uAlbedo;
layout(binding = VS_LIGHTMS_LIGHT, rgba32f) uniform image3D uLight;
layout(binding = VS_LIGHTMS_EMIT_IN, rgba32f) uniform readonly image3D uEmitIn;
layout(binding = VS_LIGHTMS_EMIT_OUT, rgba32f) uniform writeonly image3D uEmitOut;
layout(binding = VS_LIGHTMS_ORDER_OUT, rgba32f) uniform writeonly image3D uOrderOut;
layout(push_constant, std430) uniform Push
{
  VsLightScatterParams P;
};

shared vec3 sSteps[256];
shared uint sSources[256];

#define VS_COUNT(i)
#define VS_DIRECTION_SOURCE(n) sSources[n]
#include "visibility_texel.glsl"

void main()
{
  const uint D = VS_SPEC_D;
  const uint DD = D * D;
  for (uint n = gl_LocalInvocationIndex; n < DD; n += 64u)
  {
    sSteps[n] = uSteps[n].xyz;
    sSources[n] = uSources[n];
  }
  barrier();

  uvec3 cell = gl_GlobalInvocationID;
  ivec3 cells = ivec3(P.cellsX, P.cellsY, P.cellsZ);
  if (any(greaterThanEqual(ivec3(cell), cells)))
    return;
  vec4 own = imageLoad(uEmitIn, ivec3(cell));
  vec3 sum = vec3(0.0);
  uint stride = max(P.stride, 1u);
  uint side = D / stride;
  for (uint m = 0u; m < side * side; ++m)
  {
    uint n = (m % side) * stride + P.offsetX + ((m / side) * stride + P.offsetY) * D;
    float v0 = visibility_texel(cell, n, D);
    vec3 s = sSteps[n];
    vec4 previous = own;
    vec3 lastLit = own.a > 0.0 ? own.rgb / own.a : vec3(0.0); /* a I_k of the last cell with extinction */
    bool lit = own.a > 0.0;
    float t = 1.0, pending = 0.0;
    float along = 1.0, len = 1.0;
    vec3 acc = vec3(0.0);
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
}
