#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Emission-absorption ray casting (course notes 003, ch. 1), the mapper's first
 * render path: front-to-back compositing with opacity A = 1 - exp(-sigma_t dt)
 * per segment, colour from the colour transfer function, a jittered sample in
 * every segment, early termination, rays stopped at the opaque depth.
 * Output: premultiplied RGBA per pixel, rows bottom-up (OpenGL order).
 */
#include "rng.h"
#include "frame_params.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, r32f) uniform readonly image3D uVolume;
layout(std430, binding = 1) readonly buffer TransferFunction { vec4 uTF[]; };
layout(std430, binding = 2) readonly buffer Params { VsFrameParams P; };
layout(std430, binding = 3) readonly buffer Depth { float uDepth[]; };
layout(std430, binding = 4) writeonly buffer Result { vec4 uOut[]; };

#include "volume_access.glsl"

void main()
{
  uvec2 pix = gl_GlobalInvocationID.xy;
  uint W = P.viewport.x, H = P.viewport.y;
  if (pix.x >= W || pix.y >= H)
    return;
  uint idx = pix.y * W + pix.x;
  VsRng rng = vs_rng_init(pix, P.viewport.z, P.viewport.w);

  vec2 ndc = (vec2(pix) + 0.5) / vec2(W, H) * 2.0 - 1.0;
  vec4 pn = P.invViewProj * vec4(ndc, -1.0, 1.0);
  vec4 pf = P.invViewProj * vec4(ndc, 1.0, 1.0);
  vec3 o = pn.xyz / pn.w;
  vec3 d = normalize(pf.xyz / pf.w - o);
  float depth = uDepth[idx];
  float tDepth = 1e30;
  if (depth < 1.0)
  {
    vec4 pd = P.invViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    tDepth = dot(pd.xyz / pd.w - o, d);
  }

  vec3 oi = (P.worldToIndex * vec4(o, 1.0)).xyz;
  vec3 di = (P.worldToIndex * vec4(d, 0.0)).xyz;
  vec2 t = vs_intersect_box(oi, di, P.boxMin.xyz, P.boxMax.xyz);
  t = vs_clip_planes(o, d, t, P.clipPlanes, P.counts.x);
  t.x = max(t.x, 0.0);
  t.y = min(t.y, tDepth);

  vec3 color = vec3(0.0);
  float alpha = 0.0;
  ivec3 dims = ivec3(P.dims.xyz);
  float stepSize = P.march.x;
  if (t.x < t.y)
  {
    float jitter = vs_rng_float(rng);
    for (float a = t.x; a < t.y; a += stepSize)
    {
      float b = min(a + stepSize, t.y);
      float ts = a + jitter * (b - a);
      vec4 c = vs_classify(vs_sample(oi + ts * di, dims, P.counts.y), P.tf);
      float A = 1.0 - exp(-c.w * (b - a));
      color += (1.0 - alpha) * A * c.rgb;
      alpha += (1.0 - alpha) * A;
      if (alpha >= P.march.y)
        break;
    }
  }
  uOut[idx] = vec4(color, alpha);
}
