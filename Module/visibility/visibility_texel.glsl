/*
 * visibility_texel.glsl — how any shader reads one entry V(cell, n) of the visibility grid
 * (vsVisibilityGrid.h's layout: cell c's directions as a D x D tile, direction n at (n % D, n / D)).
 * GLSL only; included by direction_map.glsl (the render kernel's and the table builder's maps) and
 * by light_volume.glsl.
 *
 * The includer declares `uVisibility` (the grid image, VS_VIS_FORMAT) and defines VS_COUNT(i)
 * (empty unless it counts reads) and VS_DIRECTION_SOURCE(n) (the direction whose values direction n
 * reads: n, or the nearest swept one while a grid fills in; VisibilityGrid::DirectionSources).
 */
#ifndef VS_VISIBILITY_TEXEL_GLSL
#define VS_VISIBILITY_TEXEL_GLSL

/* Direction n of the D x D tile of `cell` (vsVisibilityGrid.h's layout), read where its source is. */
float visibility_texel(uvec3 cell, uint n, uint D)
{
  uint m = VS_DIRECTION_SOURCE(n);
  ivec3 t = ivec3(int(cell.x * D + m % D), int(cell.y * D + m / D), int(cell.z));
  VS_COUNT(2);
  return imageLoad(uVisibility, t).r;
}

#endif
