/*
 * update_order.h — the round-robin order of lazy visibility updates (von Radziewsky et al. 2017,
 * Sec. 9): which of the D x D directions of the visibility grid to re-sweep k-th.
 *
 * D = 2^n. The counter k (taken modulo D*D) has 2n bits; its even bits form x and
 * its odd bits form y (de-interleaving a Morton code), and x and y are read with
 * their bits reversed. So the least significant bits of k become the most
 * significant bits of x and y: consecutive k jump between the quadrants of the
 * octahedral map first, then between the quadrants of each quadrant, and so on.
 * Every aligned group of 4^l consecutive k holds exactly one direction in each
 * (D / 2^l) x (D / 2^l) block, and a cycle of D*D counts visits every direction once.
 * The direction index is n = y * D + x, the texel (n % D, n / D) of the grid.
 */
#ifndef VS_UPDATE_ORDER_H
#define VS_UPDATE_ORDER_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* log2 of a power of two (0 for 1). */
VS_FUNC uint vs_log2_pow2(uint side)
{
  uint n = 0u;
  while ((1u << n) < side)
    n += 1u;
  return n;
}

/* The texel (x, y) updated at count k: de-interleaved bits of k, each read in reverse. */
VS_FUNC uvec2 vs_round_robin_texel(uint k, uint side)
{
  uint n = vs_log2_pow2(side);
  uint x = 0u;
  uint y = 0u;
  for (uint i = 0u; i < n; i += 1u)
  {
    x |= ((k >> (2u * i)) & 1u) << (n - 1u - i);
    y |= ((k >> (2u * i + 1u)) & 1u) << (n - 1u - i);
  }
  return uvec2(x, y);
}

/* The direction index n = y * side + x updated at count k (side a power of two). */
VS_FUNC uint vs_round_robin_direction(uint k, uint side)
{
  uvec2 t = vs_round_robin_texel(k % (side * side), side);
  return t.y * side + t.x;
}

VS_NAMESPACE_END

#endif
