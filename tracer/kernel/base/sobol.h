// Owen-scrambled Sobol points by hashing (Burley, "Practical Hash-based Owen Scrambling",
// JCGT 9(4), 2020), in integers only, so every CPU variant and the GPU draw the same bits.
// Each 2D dimension pair of a pixel is its own scrambled copy of the first two Sobol
// dimensions (a (0,2)-sequence), and the sample index is shuffled by a nested uniform
// scramble keyed by (seed, pixel, dimension): the first 2^k samples of a pixel take the
// Sobol indices of one aligned block of 2^k, in some order, and every such block of a
// (0,2)-sequence is a (0,k,2)-net, which Owen scrambling keeps: each pair's first 2^k points
// put one point in every elementary interval of area 2^-k. Any sample is a pure function
// of (seed, pixel, sample, dimension) (DESIGN.md rule 3).
#pragma once
#include "kernel/base/philox.h"

namespace tracer {

TRACER_HD uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// Sobol dimension 0: the van der Corput radical inverse in base 2.
TRACER_HD uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

// Sobol dimension 1 (primitive polynomial x + 1, direction numbers m = 1, 3, 5, 15, 17, ...):
// its generator matrix is Pascal's triangle mod 2, so by Lucas' theorem binary digit j of
// the point is the parity of the index bits k whose positions contain j's bits (k AND j ==
// j). superset_parity computes that for all 32 digits in five shift-and-xor steps, digit j
// landing at bit j; reversing the bits puts digit j at weight 2^-(j+1).
TRACER_HD uint32_t superset_parity(uint32_t x) {
  x ^= (x >> 1) & 0x55555555u;
  x ^= (x >> 2) & 0x33333333u;
  x ^= (x >> 4) & 0x0f0f0f0fu;
  x ^= (x >> 8) & 0x00ff00ffu;
  x ^= (x >> 16) & 0x0000ffffu;
  return x;
}

TRACER_HD uint32_t sobol_dimension1(uint32_t index) { return reverse_bits(superset_parity(index)); }

// Burley's Laine-Karras-style hash: each bit is flipped by a function of the bits below it
// only, which is an Owen scramble of the bit-reversed value.
TRACER_HD uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Nested uniform (Owen) scramble: every bit flipped by a hash of the bits above it.
TRACER_HD uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// Two uniforms in [0, 1) for dimension pair `dimension` of sample `sample` of `pixel`. One
// Philox call keyed by the scene seed gives the pair's three scramble seeds; its counter
// (pixel, dimension, 0, 1) never equals a stochastic draw's (pixel, sample, dimension, 0).
TRACER_HD void sobol_uniform2(uint64_t seed, uint32_t pixel, uint32_t sample, uint32_t dimension, float& a, float& b) {
  const Philox4 keys =
      philox4x32_10({{pixel, dimension, 0u, 1u}}, static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32));
  const uint32_t index = nested_uniform_scramble(sample, keys.v[0]);
  // nested_uniform_scramble(sobol_dimension0(index)) and nested_uniform_scramble(
  // sobol_dimension1(index)) with reverse_bits(reverse_bits(x)) = x cancelled: four of the
  // eight bit reversals, which took most of the draw's time (perf)
  a = uniform_from_bits(reverse_bits(laine_karras_permutation(index, keys.v[1])));
  b = uniform_from_bits(reverse_bits(laine_karras_permutation(superset_parity(index), keys.v[2])));
}

}  // namespace tracer
