// Philox4x32-10 against Random123's published known-answer vectors.
#include <gtest/gtest.h>

#include "kernel/base/philox.h"

using namespace tracer;

namespace {
void expect_kat(Philox4 ctr, uint32_t k0, uint32_t k1, Philox4 expected) {
  const Philox4 out = philox4x32_10(ctr, k0, k1);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(out.v[i], expected.v[i]) << "word " << i;
}
}  // namespace

TEST(Philox, KnownAnswerZero) {
  expect_kat({{0, 0, 0, 0}}, 0, 0, {{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}});
}

TEST(Philox, KnownAnswerAllOnes) {
  expect_kat({{0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}}, 0xffffffffu, 0xffffffffu,
             {{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}});
}

TEST(Philox, KnownAnswerPi) {
  expect_kat({{0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}}, 0xa4093822u, 0x299f31d0u,
             {{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}});
}

TEST(Philox, UniformsAreInUnitIntervalAndNeverOne) {
  EXPECT_EQ(uniform_from_bits(0u), 0.0f);
  EXPECT_LT(uniform_from_bits(0xffffffffu), 1.0f);
  EXPECT_EQ(uniform_from_bits(0xffffffffu), 1.0f - 0x1p-24f);
}

// The counter layout: the seed's two halves are the key; pixel, sample and dimension
// each change the output.
TEST(Philox, SampleStreamsDependOnEveryCounterWord) {
  float a, b, c, d;
  sample_uniform2(1, 10, 0, 0, a, b);
  sample_uniform2(1, 10, 0, 0, c, d);
  EXPECT_EQ(a, c);
  EXPECT_EQ(b, d);
  const float base = a;
  sample_uniform2(1, 11, 0, 0, a, b);
  EXPECT_NE(a, base);
  sample_uniform2(1, 10, 1, 0, a, b);
  EXPECT_NE(a, base);
  sample_uniform2(1, 10, 0, 1, a, b);
  EXPECT_NE(a, base);
  sample_uniform2(1ull << 32 | 1, 10, 0, 0, a, b);
  EXPECT_NE(a, base);
}
