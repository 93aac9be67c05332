// The Sobol sampler (kernel/base/sobol.h): the sequence's known direction numbers, the
// scramble's block structure, and the stratification it promises: the first 2^k samples of
// every pixel's every dimension pair put one point in each elementary interval of area 2^-k.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "kernel/camera/sampler.h"

using namespace tracer;

// Dimension 1's direction numbers v_k = m_k / 2^k are those of Joe and Kuo's table
// (new-joe-kuo-6.21201, dimension 2): m = 1, 3, 5, 15, 17, 51, 85, 255, and dimension 0 is
// the van der Corput sequence 0, 1/2, 1/4, 3/4, ...
TEST(Sobol, KnownAnswersOfTheFirstTwoDimensions) {
  const uint32_t m[] = {1, 3, 5, 15, 17, 51, 85, 255};
  for (uint32_t k = 0; k < 8; ++k)
    EXPECT_EQ(sobol_dimension1(1u << k), m[k] << (31 - k)) << "direction number " << k + 1;
  const double dim0[] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double dim1[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(sobol_dimension0(i) * 0x1p-32, dim0[i]) << "point " << i;
    EXPECT_EQ(sobol_dimension1(i) * 0x1p-32, dim1[i]) << "point " << i;
  }
  EXPECT_EQ(reverse_bits(0x00000001u), 0x80000000u);
  EXPECT_EQ(reverse_bits(0x12345678u), 0x1e6a2c48u);
  EXPECT_EQ(reverse_bits64(0x0000000012345678ull), 0x1e6a2c4800000000ull);
  uint32_t a = 0x12345678u, b = 0x00000001u;
  reverse_bits_of_both(a, b);
  EXPECT_EQ(a, 0x1e6a2c48u);
  EXPECT_EQ(b, 0x80000000u);
}

// An Owen scramble permutes the values and maps every aligned block of 2^k values onto an
// aligned block of 2^k values: bit j of the output depends only on bits j and above.
TEST(Sobol, NestedUniformScrambleMapsAlignedBlocksOntoAlignedBlocks) {
  for (uint32_t seed : {0u, 1u, 0x9e3779b9u, 0xdeadbeefu}) {
    for (uint32_t k : {1u, 4u, 10u}) {
      for (uint32_t block : {0u, 1u, 77u}) {
        std::set<uint32_t> out, high;
        for (uint32_t i = 0; i < (1u << k); ++i) {
          const uint32_t y = nested_uniform_scramble((block << k) | i, seed);
          out.insert(y);
          high.insert(y >> k);
        }
        EXPECT_EQ(out.size(), 1u << k) << "seed " << seed << " k " << k;
        EXPECT_EQ(high.size(), 1u) << "seed " << seed << " k " << k;
      }
    }
  }
}

// Each elementary interval [a 2^-j, (a+1) 2^-j) x [b 2^-(k-j), (b+1) 2^-(k-j)) of the unit
// square holds exactly one of a pair's first 2^k samples, for every split j of k.
TEST(Sobol, FirstPowerOfTwoSamplesOfEveryPairAreANet) {
  for (uint64_t seed : {0ull, 7ull, 0x123456789abcdefull}) {
    for (uint32_t pixel : {0u, 1u, 4099u}) {
      for (uint32_t dimension : {kDimFilm, kDimLens, kDimFirstFree + 5u}) {
        for (uint32_t k = 0; k <= 12; ++k) {
          std::vector<float> x(1u << k), y(1u << k);
          for (uint32_t s = 0; s < (1u << k); ++s) sobol_uniform2(seed, pixel, s, dimension, x[s], y[s]);
          for (uint32_t j = 0; j <= k; ++j) {
            std::set<uint64_t> cells;
            for (uint32_t s = 0; s < (1u << k); ++s) {
              const uint64_t cx = static_cast<uint64_t>(x[s] * static_cast<float>(1u << j));
              const uint64_t cy = static_cast<uint64_t>(y[s] * static_cast<float>(1u << (k - j)));
              cells.insert(cx << 32 | cy);
            }
            ASSERT_EQ(cells.size(), 1u << k)
                << "seed " << seed << " pixel " << pixel << " dimension " << dimension << " k " << k << " j " << j;
          }
        }
      }
    }
  }
}

// Different pixels, dimensions and seeds draw differently scrambled points, and a sample is
// the same whichever range of samples it is drawn in (a pure function of its counters).
TEST(Sobol, PixelsDimensionsAndSeedsAreDecorrelated) {
  float a0, b0, a1, b1;
  std::set<std::pair<float, float>> firsts;
  for (uint32_t pixel = 0; pixel < 64; ++pixel)
    for (uint32_t dimension = 0; dimension < 8; ++dimension) {
      sobol_uniform2(1u, pixel, 0u, dimension, a0, b0);
      firsts.insert({a0, b0});
    }
  EXPECT_EQ(firsts.size(), 64u * 8u);
  sobol_uniform2(1u, 5u, 3u, 2u, a0, b0);
  sobol_uniform2(2u, 5u, 3u, 2u, a1, b1);
  EXPECT_FALSE(a0 == a1 && b0 == b1);
}

// The sampler dispatch: `sobol` draws the Sobol pairs; every other sampler the Philox pairs.
TEST(Sobol, DrawUniformPicksTheSamplersPairs) {
  float a, b, x, y;
  draw_uniform2(SamplerKind::Sobol, 3u, 10u, 4u, kDimLens, a, b);
  sobol_uniform2(3u, 10u, 4u, kDimLens, x, y);
  EXPECT_EQ(a, x);
  EXPECT_EQ(b, y);
  draw_uniform2(SamplerKind::Stratified, 3u, 10u, 4u, kDimLens, a, b);
  sample_uniform2(3u, 10u, 4u, kDimLens, x, y);
  EXPECT_EQ(a, x);
  EXPECT_EQ(b, y);
  film_offset(SamplerKind::Sobol, 1u, 3u, 10u, 4u, a, b);
  sobol_uniform2(3u, 10u, 4u, kDimFilm, x, y);
  EXPECT_EQ(a, x);
  EXPECT_EQ(b, y);
}

// The pair is each Sobol dimension of the shuffled index, Owen-scrambled: the composition of
// the functions tested above, whatever reversals sobol_uniform2 cancels.
TEST(Sobol, PairIsTheScrambledDimensionsOfTheShuffledIndex) {
  const uint64_t seed = 0x0123456789abcdefull;
  for (uint32_t pixel : {0u, 7u, 123456u})
    for (uint32_t dimension = 0; dimension < 12; ++dimension)
      for (uint32_t sample : {0u, 1u, 2u, 3u, 17u, 255u, 4096u, 0xfffffffeu}) {
        const SobolKeys keys = sobol_keys(seed, pixel, dimension);
        const uint32_t index = nested_uniform_scramble(sample, keys.index);
        float a, b;
        sobol_uniform2(seed, pixel, sample, dimension, a, b);
        EXPECT_EQ(a, uniform_from_bits(nested_uniform_scramble(sobol_dimension0(index), keys.x)));
        EXPECT_EQ(b, uniform_from_bits(nested_uniform_scramble(sobol_dimension1(index), keys.y)));
      }
}
