#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * denoise.comp — the display's guided filter of the Monte Carlo estimate, the preview its guide
 * (denoise_params.h has the model; vsDenoisePass.cxx runs the stages). One invocation per pixel; the
 * stage is the specialization constant 0, so that each stage's pipeline holds its own code only (lavapipe
 * runs both sides of a branch). Nothing random: the same inputs give the same image.
 */
#include "bindings.h"
#include "denoise_params.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const uint VS_DENOISE_STAGE = 0u;
layout(std430, binding = VS_DENOISE_INPUT) readonly buffer Input { vec4 uInput[]; };
layout(std430, binding = VS_DENOISE_SRC) readonly buffer Src { vec4 uSrc[]; };
layout(std430, binding = VS_DENOISE_DST) writeonly buffer Dst { vec4 uDst[]; };
layout(std430, binding = VS_DENOISE_OUTPUT) writeonly buffer Output { vec4 uOutput[]; };
layout(push_constant) uniform Push { VsDenoiseParams P; };

void main()
{
  uvec2 pix = gl_GlobalInvocationID.xy;
  if (pix.x >= P.width || pix.y >= P.height)
    return;
  uint plane = P.width * P.height;
  uint i = pix.y * P.width + pix.x;
  if (VS_DENOISE_STAGE == VS_DENOISE_STAGE_MOMENTS)
  {
    vec3 m = uInput[i].rgb;
    vec3 g = uInput[plane + i].rgb;
    vec3 s2 = uInput[2u * plane + i].rgb;
    float w = vs_denoise_noisy(m, s2) ? 1.0 : 0.0; // exact pixels (no variance) take no part in the fits
    uDst[i] = vec4(w * g, w);
    uDst[plane + i] = vec4(w * m, 0.0);
    uDst[2u * plane + i] = vec4(w * g * g, 0.0);
    uDst[3u * plane + i] = vec4(w * g * m, 0.0);
    uDst[4u * plane + i] = vec4(w * s2, 0.0);
  }
  else if (VS_DENOISE_STAGE == VS_DENOISE_STAGE_BOX)
  {
    // The mean over the window's pixels inside the image along one axis: the two axes' means in turn
    // are the mean over the window's rectangle inside the image.
    int r = int(P.radius);
    int at = P.axis == 0u ? int(pix.x) : int(pix.y);
    int size = P.axis == 0u ? int(P.width) : int(P.height);
    int lo = max(at - r, 0), hi = min(at + r, size - 1);
    int stride = P.axis == 0u ? 1 : int(P.width);
    int first = int(i) - (at - lo) * stride;
    float inv = 1.0 / float(hi - lo + 1);
    for (uint k = 0u; k < P.planes; ++k)
    {
      vec4 sum = vec4(0.0);
      int j = first + int(k * plane);
      for (int t = lo; t <= hi; ++t, j += stride)
        sum += uSrc[j];
      uDst[k * plane + i] = sum * inv;
    }
  }
  else if (VS_DENOISE_STAGE == VS_DENOISE_STAGE_COEFFICIENTS)
  {
    // The window's fit over its noisy pixels (W: their share of the window), weighted by W in the
    // coefficients' means; a window without one fits nothing.
    float W = uSrc[i].a;
    vec3 a = vec3(1.0), b = vec3(0.0);
    if (W > 0.0)
    {
      vec3 g = uSrc[i].rgb / W, m = uSrc[plane + i].rgb / W, gg = uSrc[2u * plane + i].rgb / W;
      vec3 gm = uSrc[3u * plane + i].rgb / W, s2 = uSrc[4u * plane + i].rgb / W;
      for (int c = 0; c < 3; ++c)
        a[c] = vs_denoise_slope(g[c], m[c], gg[c], gm[c], s2[c], P.priorScale / W);
      b = m - a * g;
    }
    uDst[i] = vec4(W * a, W);
    uDst[plane + i] = vec4(W * b, 0.0);
  }
  else
  {
    vec4 m = uInput[i];
    vec3 g = uInput[plane + i].rgb;
    vec3 s2 = uInput[2u * plane + i].rgb;
    float W = uSrc[i].a;
    vec3 filtered = m.rgb; // an exact pixel is shown as it is
    if (W > 0.0 && vs_denoise_noisy(m.rgb, s2))
      filtered = max((uSrc[i].rgb * g + uSrc[plane + i].rgb) / W, vec3(0.0));
    uOutput[i] = vec4(filtered, m.a);
  }
}
