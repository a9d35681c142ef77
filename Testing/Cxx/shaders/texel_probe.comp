#version 460
/*
 * texel_probe.comp — reads a buffer as uniform texel buffers at per-lane (divergent) indices, the
 * way the render kernel reads its tables: invocation i reads texel idx[i] of an rgba32f view and
 * of an r32ui view and writes both back.
 */
layout(local_size_x = 8) in;
layout(binding = 0) uniform samplerBuffer uFloats;
layout(binding = 1) uniform usamplerBuffer uUints;
layout(std430, binding = 2) readonly buffer Index { uint uIndex[]; };
layout(std430, binding = 3) writeonly buffer Out { vec4 uOut[]; };
layout(std430, binding = 4) writeonly buffer OutU { uint uOutU[]; };

void main()
{
  uint i = gl_GlobalInvocationID.x;
  uOut[i] = texelFetch(uFloats, int(uIndex[i]));
  uOutU[i] = texelFetch(uUints, int(uIndex[i])).r;
}
