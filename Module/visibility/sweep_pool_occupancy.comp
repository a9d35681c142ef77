#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Occupancy of the pooled extinction volume: per brick of B pooled texels, the max over
 * the texels its trilinear footprint reads ([i B - 1, (i + 1) B], clamped). 0 means the
 * pooled interpolant is 0 throughout the brick, so the march skips it whole.
 */
#include "bindings.h"
#include "pool_params.h"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = VS_OCCUPANCY_POOLED, r32f) uniform readonly image3D uPooled;
layout(binding = VS_OCCUPANCY_OUTPUT, r32f) uniform writeonly image3D uOccupancy;
layout(push_constant) uniform Push { VsOccupancyPush pc; };

void main()
{
  ivec3 i = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(i, pc.bricks)))
    return;
  ivec3 lo = max(i * pc.brickTexels - 1, ivec3(0));
  ivec3 hi = min((i + 1) * pc.brickTexels, pc.pooled - 1);
  float largest = 0.0;
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
        largest = max(largest, imageLoad(uPooled, ivec3(x, y, z)).r);
  imageStore(uOccupancy, i, vec4(largest));
}
