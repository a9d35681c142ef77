/*
 * grid_fill.glsl — directions of a progressively filled visibility grid that are not swept yet
 * take, in every cell, the visibility of the nearest swept direction (vsVisibilityGridUpdater.h).
 * Included by grid_fill_<format>.comp, which defines VS_VIS_FORMAT.
 *
 * The grid only shapes TwoStep's pdf, so any value is unbiased; this one keeps a partly swept grid
 * from contradicting itself: at visibility 1 an unswept sky beside a swept, shadowed sun made the
 * sun's samples rare and heavy at lit points in cells whose centre is in shadow.
 */
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(binding = 0, VS_VIS_FORMAT) uniform image3D uGrid;
/* Pairs (unswept direction, the swept direction it copies), as 2 uints each. */
layout(std430, binding = 1) readonly buffer Copies { uint uCopies[]; };
layout(push_constant) uniform Push
{
  uvec4 cells; /* cells per axis, w: D (directions per side) */
  uint copies; /* pairs in uCopies */
} pc;

void main()
{
  uint id = gl_GlobalInvocationID.x;
  uint cx = pc.cells.x, cy = pc.cells.y, D = pc.cells.w;
  if (id >= cx * cy * pc.cells.z)
    return;
  ivec3 base = ivec3(int((id % cx) * D), int(((id / cx) % cy) * D), int(id / (cx * cy)));
  for (uint k = 0u; k < pc.copies; ++k)
  {
    uint to = uCopies[2u * k], from = uCopies[2u * k + 1u];
    vec4 v = imageLoad(uGrid, base + ivec3(int(from % D), int(from / D), 0));
    imageStore(uGrid, base + ivec3(int(to % D), int(to / D), 0), v);
  }
}
