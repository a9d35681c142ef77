#version 460
#extension GL_GOOGLE_include_directive : require
/*
 * An integer-coded volume's float image from its quads (vsDeviceVolume.h): voxel (x, y, z) is the
 * low byte of quad texel (x, y, z) plus the offset of code 0, the same float the upload made of it
 * (an integer within 255 of the offset, both below 2^24 in magnitude: exact). Run when a pass first
 * reads the float image; the render kernel and the pool read the quads and never need it.
 */
#include "bindings.h"
#include "quads_params.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = VS_QUADS_INPUT, r32ui) uniform readonly uimage3D uQuads;
layout(binding = VS_QUADS_OUTPUT, r32f) uniform writeonly image3D uScalars;
layout(push_constant) uniform Push { VsQuadsPush pc; };

void main()
{
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, pc.dims)))
    return;
  imageStore(uScalars, v, vec4(float(imageLoad(uQuads, v).r & 0xffu) + pc.quadZero));
}
