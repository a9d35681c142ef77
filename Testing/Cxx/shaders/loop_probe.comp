#version 460
/*
 * loop_probe.comp — how many loop iterations one invocation may run. Each invocation runs
 * pc.outer iterations of an outer loop, each with pc.inner iterations of an inner one, and writes
 * how many inner iterations it completed. On lavapipe, llvmpipe's loop limiter (one counter per
 * group of SIMD lanes, shared by every loop of the shader, LP_MAX_TGSI_LOOP_ITERATIONS = 65535)
 * ends every loop early once the shader's back-edges reach it, silently.
 */
layout(local_size_x = 8) in;
layout(std430, binding = 0) writeonly buffer Out { uint uOut[]; };
layout(push_constant) uniform Push { uint outer; uint inner; } pc;

void main()
{
  uint done = 0u;
  for (uint i = 0u; i < pc.outer; ++i)
    for (uint j = 0u; j < pc.inner; ++j)
      done += 1u;
  uOut[gl_GlobalInvocationID.x] = done;
}
