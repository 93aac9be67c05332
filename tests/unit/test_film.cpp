// The film's fixed-point accumulation (kernel/base/film.h, docs/determinism.md rule 5): each sample is
// rounded to the nearest 2^-32 of radiance, halves away from zero, so the bias a sample adds
// is at most half a unit; a rejected sample adds nothing to any channel.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "kernel/base/film.h"
#include "render/partial_file.h"

using namespace tracer;

namespace {
constexpr float kUnit = 0x1p-32f;  // one film unit of radiance

FilmSum empty_film() { return FilmSum{{0, 0, 0}, 0u, 0u}; }
}  // namespace

TEST(Film, EachSampleRoundsToTheNearestUnitAndHalvesAwayFromZero) {
  EXPECT_EQ(to_film_units(1.25f * kUnit), 1);
  EXPECT_EQ(to_film_units(1.5f * kUnit), 2);
  EXPECT_EQ(to_film_units(1.75f * kUnit), 2);
  EXPECT_EQ(to_film_units(0.5f * kUnit), 1);
  EXPECT_EQ(to_film_units(0.25f * kUnit), 0);
  EXPECT_EQ(to_film_units(-1.5f * kUnit), -2);
  EXPECT_EQ(to_film_units(-1.25f * kUnit), -1);
  EXPECT_EQ(to_film_units(1.0f), int64_t{1} << 32);
  EXPECT_EQ(to_film_units(0.0f), 0);
}

// |film_mean(one sample v) - v| <= half a unit, plus the half ulp of rounding the mean to
// float once: the film is unbiased to within 2^-33 per sample at any radiance.
TEST(Film, AOneSampleMeanIsWithinHalfAUnitOfTheSample) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> exponent(-40.0f, 8.0f);
  for (int i = 0; i < 100000; ++i) {
    const float v = std::exp2(exponent(rng));
    FilmSum sum = empty_film();
    ASSERT_TRUE(film_add(sum, {v, -v, v}));
    const Vec3 mean = film_mean(sum, 1u);
    const double bound = 0.5 * kUnit + 0.5 * std::ldexp(1.0, std::ilogb(v) - 23);
    ASSERT_LE(std::abs(static_cast<double>(mean.x) - v), bound) << "v = " << v;
    ASSERT_LE(std::abs(static_cast<double>(mean.y) + v), bound) << "v = " << v;
  }
}

TEST(Film, ARejectedSampleAddsToNoChannelAndIsCounted) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  FilmSum sum = empty_film();
  ASSERT_TRUE(film_add(sum, {0.5f, 0.25f, 0.125f}));
  const FilmSum before = sum;
  EXPECT_FALSE(film_add(sum, {1.0f, nan, 1.0f}));
  EXPECT_FALSE(film_add(sum, {1.0f, 1.0f, -inf}));
  EXPECT_FALSE(film_add(sum, {1.0f, 1.0f, 0x1p30f}));  // samples of 2^30 or more overflow
  for (int c = 0; c < 3; ++c) EXPECT_EQ(sum.rgb[c], before.rgb[c]) << "channel " << c;
  EXPECT_EQ(sum.nonfinite, 2u);
  EXPECT_EQ(sum.overflow, 1u);
  // A sample that would carry the sum past 2^62 is left out whole as well.
  sum.rgb[2] = kFilmSumLimit - 1;
  EXPECT_FALSE(film_add(sum, {1.0f, 1.0f, 1.0f}));
  EXPECT_EQ(sum.rgb[0], before.rgb[0]);
  EXPECT_EQ(sum.overflow, 2u);
}

// Parts' sums add exactly, counts included, and a pixel whose sum would leave the film's range
// stops the addition there, that pixel and those after it untouched (merge and the viewer).
TEST(Film, PartsAddExactlyAndAnOverflowingPixelStopsTheAddition) {
  FilmBuffer total{2, 1, {0, 3}, {FilmSum{{5, -7, 1}, 1u, 0u}, FilmSum{{kFilmSumLimit - 1, 0, 0}, 0u, 0u}}};
  const FilmBuffer part{2, 1, {3, 4}, {FilmSum{{10, 7, -1}, 0u, 2u}, FilmSum{{1, 0, 0}, 0u, 0u}}};
  EXPECT_EQ(add_film_sums(total, part), 2u);
  EXPECT_EQ(total.pixels[0].rgb[0], 15);
  EXPECT_EQ(total.pixels[0].rgb[1], 0);
  EXPECT_EQ(total.pixels[0].rgb[2], 0);
  EXPECT_EQ(total.pixels[0].nonfinite, 1u);
  EXPECT_EQ(total.pixels[0].overflow, 2u);
  EXPECT_EQ(total.pixels[1].rgb[0], kFilmSumLimit);
  EXPECT_EQ(add_film_sums(total, part), 1u) << "kFilmSumLimit + 1 is past the range";
  EXPECT_EQ(total.pixels[1].rgb[0], kFilmSumLimit) << "the overflowing pixel was changed";
}
