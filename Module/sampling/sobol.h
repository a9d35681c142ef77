/*
 * sobol.h — a pixel's 2D sample points as an Owen-scrambled, shuffled Sobol (0,2)-sequence
 * (Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020).
 *
 * The first two Sobol dimensions are a (0,2)-sequence: any 2^m consecutive points from a
 * multiple of 2^m put exactly one point in every elementary box of area 2^-m. Owen scrambling
 * (nested uniform, by a hash per seed) keeps that and makes every single point uniform on the
 * unit square, so an estimator fed with it is unbiased, while a pixel's first N points fill its
 * square far more evenly than N independent ones: a progressive render's error falls faster in
 * the dimensions where the integrand is smooth (the pixel footprint, the light direction).
 * Shuffling the index by a scramble of its own (another seed) decorrelates two such sequences
 * used for different dimensions of the same sample (the pixel jitter and the light direction).
 */
#ifndef VS_SOBOL_H
#define VS_SOBOL_H
#include "vs_prelude.h"

VS_NAMESPACE_BEGIN

/* Laine and Karras' hash: a permutation of the uint's bits that only lets bits affect higher ones,
 * i.e. a nested uniform scramble when applied to a bit-reversed value (Burley 2020, Listing 1). */
VS_FUNC uint vs_laine_karras_permutation(uint x, uint seed)
{
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

/* Owen's nested uniform scramble of a 32-bit fixed-point coordinate (or index). */
VS_FUNC uint vs_nested_uniform_scramble(uint x, uint seed)
{
  return bitfieldReverse(vs_laine_karras_permutation(bitfieldReverse(x), seed));
}

/* Sobol's second dimension of index i as 32-bit fixed point (the first is bitfieldReverse(i)).
 * Its generator matrix is Pascal's triangle mod 2: bit 31 - j of the result is the parity of the
 * set bits k of i with C(k, j) odd, i.e. (Lucas) with j a subset of k's bits. That superset-parity
 * transform over the 5-bit positions takes 5 masked shifts, no loop (lavapipe counts every loop's
 * back-edges against the kernel's budget). vs_sobol_dimension1_reference is the textbook loop. */
VS_FUNC uint vs_sobol_dimension1(uint i)
{
  uint g = i;
  g ^= (g >> 1u) & 0x55555555u;
  g ^= (g >> 2u) & 0x33333333u;
  g ^= (g >> 4u) & 0x0F0F0F0Fu;
  g ^= (g >> 8u) & 0x00FF00FFu;
  g ^= (g >> 16u) & 0x0000FFFFu;
  return bitfieldReverse(g);
}

VS_FUNC uint vs_sobol_dimension1_reference(uint i)
{
  uint v = 0x80000000u, r = 0u;
  for (uint k = 0u; k < 32u; ++k)
  {
    if ((i & (1u << k)) != 0u)
      r ^= v;
    v ^= v >> 1u;
  }
  return r;
}

/* Decorrelated seeds from one (a splitmix-style finaliser). */
VS_FUNC uint vs_hash_seed(uint seed, uint salt)
{
  uint x = seed ^ (salt * 0x9E3779B9u);
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

/* Point `index` of the shuffled, Owen-scrambled Sobol (0,2)-sequence of `seed`, in [0,1)^2 with the
 * top 24 bits (every value exact in float, as vs_rng_vec2's). */
VS_FUNC vec2 vs_sobol_2d(uint index, uint seed)
{
  uint i = vs_nested_uniform_scramble(index, vs_hash_seed(seed, 0u));
  uint x = vs_nested_uniform_scramble(bitfieldReverse(i), vs_hash_seed(seed, 1u));
  uint y = vs_nested_uniform_scramble(vs_sobol_dimension1(i), vs_hash_seed(seed, 2u));
  return vec2(float(x >> 8u), float(y >> 8u)) * (1.0f / 16777216.0f);
}

VS_NAMESPACE_END

#endif
