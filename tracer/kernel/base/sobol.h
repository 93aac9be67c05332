// Owen-scrambled Sobol points by hashing (Burley, "Practical Hash-based Owen Scrambling",
// JCGT 9(4), 2020), in integers only, so every CPU variant and the GPU draw the same bits.
// Each 2D dimension pair of a pixel is its own scrambled copy of the first two Sobol
// dimensions (a (0,2)-sequence), and the sample index is shuffled by a nested uniform
// scramble keyed by (seed, pixel, dimension): the first 2^k samples of a pixel take the
// Sobol indices of one aligned block of 2^k, in some order, and every such block of a
// (0,2)-sequence is a (0,k,2)-net, which Owen scrambling keeps: each pair's first 2^k points
// put one point in every elementary interval of area 2^-k. Any sample is a pure function
// of (seed, pixel, sample, dimension) (docs/determinism.md rule 3).
#pragma once
#include "kernel/base/philox.h"

namespace tracer {

// The GPU reverses a word in one instruction (brev); the CPU in swaps of halves, which the
// compiler turns into a byte swap and three shift-and-mask steps.
TRACER_HD uint32_t reverse_bits(uint32_t x) {
#if defined(__CUDA_ARCH__)
  return __brev(x);
#else
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
#endif
}

TRACER_HD uint64_t reverse_bits64(uint64_t x) {
  x = ((x >> 1) & 0x5555555555555555ull) | ((x & 0x5555555555555555ull) << 1);
  x = ((x >> 2) & 0x3333333333333333ull) | ((x & 0x3333333333333333ull) << 2);
  x = ((x >> 4) & 0x0f0f0f0f0f0f0f0full) | ((x & 0x0f0f0f0f0f0f0f0full) << 4);
  x = ((x >> 8) & 0x00ff00ff00ff00ffull) | ((x & 0x00ff00ff00ff00ffull) << 8);
  x = ((x >> 16) & 0x0000ffff0000ffffull) | ((x & 0x0000ffff0000ffffull) << 16);
  return (x >> 32) | (x << 32);
}

// reverse_bits of both words: on the CPU one 64-bit reversal of (a, b), whose low half is a's
// and high half b's (the same steps, half the instructions of two); on the GPU two brev.
TRACER_HD void reverse_bits_of_both(uint32_t& a, uint32_t& b) {
#if defined(__CUDA_ARCH__)
  a = __brev(a);
  b = __brev(b);
#else
  const uint64_t r = reverse_bits64(static_cast<uint64_t>(a) << 32 | b);
  a = static_cast<uint32_t>(r);
  b = static_cast<uint32_t>(r >> 32);
#endif
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

// SplitMix64's output function (Steele, Lea and Flood, OOPSLA 2014; Stafford's Mix13
// constants): a bijection of 64-bit words whose every output bit depends on every input bit.
TRACER_HD uint64_t splitmix64_mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// The three scramble seeds of one dimension pair of one pixel: the sample index's shuffle and
// the two coordinates' scrambles. Two SplitMix64 steps give the first two seeds (the counter
// plus the Weyl increment, then the scene seed plus the first step's output), one more step
// (its output plus the increment) the third: six 64-bit multiplies where a Philox4x32-10 call
// took twenty 32x32 products in ten dependent rounds. Distinct (pixel, dimension) give
// distinct first words for a seed, each step being a bijection.
struct SobolKeys {
  uint32_t index, x, y;
};

TRACER_HD SobolKeys sobol_keys(uint64_t seed, uint32_t pixel, uint32_t dimension) {
  constexpr uint64_t kWeyl = 0x9e3779b97f4a7c15ull;  // 2^64 / golden ratio, SplitMix64's increment
  const uint64_t counter = static_cast<uint64_t>(pixel) << 32 | dimension;
  const uint64_t h = splitmix64_mix(seed + splitmix64_mix(counter + kWeyl));
  const uint64_t g = splitmix64_mix(h + kWeyl);
  return {static_cast<uint32_t>(h), static_cast<uint32_t>(h >> 32), static_cast<uint32_t>(g)};
}

// Two uniforms in [0, 1) for dimension pair `dimension` of sample `sample` of `pixel`.
TRACER_HD void sobol_uniform2(uint64_t seed, uint32_t pixel, uint32_t sample, uint32_t dimension, float& a, float& b) {
  const SobolKeys keys = sobol_keys(seed, pixel, dimension);
  const uint32_t index = nested_uniform_scramble(sample, keys.index);
  // nested_uniform_scramble(sobol_dimension0(index)) and nested_uniform_scramble(
  // sobol_dimension1(index)) with reverse_bits(reverse_bits(x)) = x cancelled: four of the
  // eight bit reversals, which took most of the draw's time (perf)
  uint32_t x = laine_karras_permutation(index, keys.x), y = laine_karras_permutation(superset_parity(index), keys.y);
  reverse_bits_of_both(x, y);
  a = uniform_from_bits(x);
  b = uniform_from_bits(y);
}

}  // namespace tracer
