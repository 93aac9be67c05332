// Philox4x32-10 counter-based generator (Salmon et al., "Parallel random numbers: as easy
// as 1, 2, 3", SC 2011; constants from Random123). A number is a pure function of
// (key, counter): key = scene seed, counter = (pixel, sample, dimension, 0) (docs/determinism.md rule 3).
#pragma once
#include "kernel/base/platform.h"

namespace tracer {

struct Philox4 {
  uint32_t v[4];
};

TRACER_HD Philox4 philox4x32_10(Philox4 ctr, uint32_t key0, uint32_t key1) {
  constexpr uint32_t kMul0 = 0xD2511F53u, kMul1 = 0xCD9E8D57u;
  constexpr uint32_t kWeyl0 = 0x9E3779B9u, kWeyl1 = 0xBB67AE85u;
  for (int round = 0; round < 10; ++round) {
    const uint64_t p0 = static_cast<uint64_t>(kMul0) * ctr.v[0];
    const uint64_t p1 = static_cast<uint64_t>(kMul1) * ctr.v[2];
    const uint32_t hi0 = static_cast<uint32_t>(p0 >> 32), lo0 = static_cast<uint32_t>(p0);
    const uint32_t hi1 = static_cast<uint32_t>(p1 >> 32), lo1 = static_cast<uint32_t>(p1);
    ctr = {{hi1 ^ ctr.v[1] ^ key0, lo1, hi0 ^ ctr.v[3] ^ key1, lo0}};
    key0 += kWeyl0;
    key1 += kWeyl1;
  }
  return ctr;
}

// A uniform float in [0, 1) from the top 24 bits of a word: exact, never 1.
TRACER_HD float uniform_from_bits(uint32_t u) { return static_cast<float>(u >> 8) * 0x1p-24f; }

// Two uniforms for dimension `dimension` of one sample of one pixel. The counter is
// (pixel, sample, dimension, 0) and the key the 64-bit seed: no state crosses pixels or
// samples, so thread count, tile order and device cannot change a number.
TRACER_HD void sample_uniform2(uint64_t seed, uint32_t pixel, uint32_t sample, uint32_t dimension, float& a, float& b) {
  const Philox4 r =
      philox4x32_10({{pixel, sample, dimension, 0u}}, static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32));
  a = uniform_from_bits(r.v[0]);
  b = uniform_from_bits(r.v[1]);
}

// Dimensions used by the camera; integrators start at kDimFirstFree.
constexpr uint32_t kDimFilm = 0, kDimLens = 1, kDimFirstFree = 2;

}  // namespace tracer
