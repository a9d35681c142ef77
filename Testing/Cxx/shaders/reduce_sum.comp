#version 460
/*
 * Parallel sum of a float array, one partial sum per workgroup (shared-memory
 * tree). Used as a building block and as the core's self-test against the CPU.
 */
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly buffer In { float uIn[]; };
layout(std430, binding = 1) writeonly buffer Out { float uOut[]; };
layout(push_constant) uniform Push { uint count; } pc;

shared float partial[256];

void main()
{
  uint i = gl_GlobalInvocationID.x;
  partial[gl_LocalInvocationID.x] = i < pc.count ? uIn[i] : 0.0;
  barrier();
  for (uint s = 128u; s > 0u; s >>= 1u)
  {
    if (gl_LocalInvocationID.x < s)
      partial[gl_LocalInvocationID.x] += partial[gl_LocalInvocationID.x + s];
    barrier();
  }
  if (gl_LocalInvocationID.x == 0u)
    uOut[gl_WorkGroupID.x] = partial[0];
}
