#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * strategy_samples.comp — the shared strategies (strategies.h) compiled for the device:
 * one direction and pdf per uniform sample u, for TestSamplingDevice to hold against
 * the same header compiled as C++ and against its pdf (chi-square).
 */
#include "strategies.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Uniforms { vec2 uU[]; };
layout(std430, binding = 1) readonly buffer DirectionMap { float uMap[]; };
layout(std430, binding = 2) readonly buffer EnvMips { float uMips[]; };
layout(std430, binding = 3) writeonly buffer Samples { vec4 uOut[]; };
layout(push_constant) uniform Push { uvec4 p; } pc; /* strategy, D, K, count */

float vs_env_mip(uint index)
{
  return uMips[index];
}

float vs_map_value(uint n)
{
  return uMap[n];
}

void main()
{
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.p.w)
    return;
  float pdf;
  vec3 d = vs_sample_direction(pc.p.x, pc.p.y, pc.p.z, uU[i], pdf);
  uOut[i] = vec4(d, pdf);
}
