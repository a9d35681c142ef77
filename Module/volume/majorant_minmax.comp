#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * Per brick of B^3 voxels, the range of the scalars its trilinear samples can take:
 * min and max over voxels [bB, (b+1)B] (inclusive: a sample in the brick interpolates
 * the next voxel too). Non-finite voxels are skipped; an all-NaN brick gets (1, 0)
 * (empty range); z is 1 where any voxel is non-finite (its samples are empty space, so the brick's
 * smallest extinction is 0). The host turns ranges into majorants with the transfer function,
 * so a transfer-function change needs no pass over the voxels.
 */
#include "bindings.h"
#include "majorant_params.h"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = VS_RANGES_VOLUME, r32f) uniform readonly image3D uVolume;
layout(std430, binding = VS_RANGES_OUTPUT) writeonly buffer Ranges { vec4 uRange[]; };
layout(push_constant) uniform Push { VsMajorantPush pc; };

void main()
{
  uvec3 b = gl_GlobalInvocationID;
  if (any(greaterThanEqual(b, pc.bricks)))
    return;
  int B = int(pc.brickSize);
  ivec3 lo = ivec3(b) * B;
  ivec3 hi = min(lo + B, pc.dims - 1);
  float mn = 3.4e38, mx = -3.4e38;
  bool gap = false;
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
      {
        float v = imageLoad(uVolume, ivec3(x, y, z)).r;
        if (!isnan(v))
        {
          mn = min(mn, v);
          mx = max(mx, v);
        }
        else
          gap = true;
      }
  uRange[(b.z * pc.bricks.y + b.y) * pc.bricks.x + b.x] =
    vec4(mn <= mx ? vec2(mn, mx) : vec2(1.0, 0.0), gap ? 1.0 : 0.0, 0.0);
}
