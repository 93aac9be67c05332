// Adaptive sampling (render.noise_threshold) against what it promises: the error estimate on
// known half sums, a zero-variance furnace stopping every pixel at min_spp, a half-noisy
// image spending its samples on the noisy half, and a pixel that never stops equal to the
// uniform render's pixel bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/integrator/adaptive.h"
#include "render/render_adaptive.h"
#include "test_util.h"

namespace tracer {
namespace {

FilmSum sum_of(double r, double g, double b) {
  const auto units = [](double v) { return static_cast<int64_t>(std::llround(v * kFilmUnits)); };
  return {{units(r), units(g), units(b)}, 0u, 0u};
}

AdaptiveFilm render_adaptive(const std::string& json, const RenderOverrides& ov, int threads = 0) {
  RenderStats stats;
  AdaptiveFilm film = render_cpu_adaptive(test::scene_from(json, ov), threads, stats);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  return film;
}

// A sky of radiance 1 and an albedo-1 Lambert sphere: every sample of every pixel is 1.
std::string white_furnace() {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": [0, 0, 0], "vfov": 35},
    "film": {"width": 32, "height": 24},
    "render": {"integrator": "path", "spp": 256, "sampler": "sobol", "max_depth": 16},
    "background": {"type": "constant", "radiance": [1, 1, 1]},
    "materials": {"m": {"type": "lambert", "albedo": [1, 1, 1]}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
}

// The left of the image sees a sky of radiance 1 (no variance); the right, a huge Lambert
// sphere whose surface passes through the origin, lit by the sky (no variance: it is convex)
// and by a small emitting sphere out of view that only BSDF samples find (nee off: noisy).
std::string half_noisy(const std::string& sampler) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": [0, 0, 0], "vfov": 35},
    "film": {"width": 48, "height": 32},
    "render": {"integrator": "path", "spp": 256, "sampler": ")" +
         sampler + R"(", "max_depth": 4, "nee": false},
    "background": {"type": "constant", "radiance": [1, 1, 1]},
    "materials": {"grey": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]},
                  "lamp": {"type": "emissive", "radiance": [10, 10, 10]}},
    "shapes": [{"type": "sphere", "center": [1000, 0, 0], "radius": 1000, "material": "grey"},
               {"type": "sphere", "center": [-4, 0, 3], "radius": 2, "material": "lamp"}]})";
}

TEST(AdaptiveSampling, ErrorEstimateIsHalfTheHalvesDifferenceOverTheMean) {
  // 8 samples: even mean 1.0, odd mean 0.8 in every channel; whole mean 0.9.
  const FilmSum even = sum_of(4.0, 4.0, 4.0), odd = sum_of(3.2, 3.2, 3.2);
  EXPECT_NEAR(pixel_relative_error(even, odd, 8), 0.5 * 0.2 / 0.9, 1e-9);  // 3.2 is rounded to film units
  EXPECT_TRUE(pixel_converged(even, odd, 8, 0.12f));
  EXPECT_FALSE(pixel_converged(even, odd, 8, 0.11f));
  // Odd counts: 5 even samples and 4 odd ones with the same mean have no difference.
  EXPECT_EQ(pixel_relative_error(sum_of(5.0, 0.0, 2.5), sum_of(4.0, 0.0, 2.0), 9), 0.0);
  // All zero converges; a difference around a zero mean never does.
  EXPECT_EQ(pixel_relative_error(sum_of(0, 0, 0), sum_of(0, 0, 0), 4), 0.0);
  EXPECT_EQ(pixel_relative_error(sum_of(1, 0, 0), sum_of(-1, 0, 0), 4), static_cast<double>(kInfinity));
}

TEST(AdaptiveSampling, APixelKeepsSamplingWhileANeighbourIsNotConverged) {
  // 4 x 3 pixels, only (3, 2) not converged: it and its neighbours (2..3, 1..2) keep sampling.
  std::vector<uint8_t> unconverged(12, 0);
  unconverged[2 * 4 + 3] = 1;
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      EXPECT_EQ(neighbourhood_unconverged(unconverged.data(), 4, 3, x, y), x >= 2 && y >= 1) << x << "," << y;
}

TEST(AdaptiveSampling, CheckpointsDoubleFromTheMinimumToTheMaximum) {
  EXPECT_EQ(adaptive_checkpoints(16, 256), (std::vector<uint32_t>{16, 32, 64, 128, 256}));
  EXPECT_EQ(adaptive_checkpoints(12, 100), (std::vector<uint32_t>{12, 24, 48, 96, 100}));
  EXPECT_EQ(adaptive_checkpoints(16, 8), (std::vector<uint32_t>{8}));
}

// Every sample of the white furnace is 1: every pixel stops at min_spp, by the per-pixel
// threshold and by the image's target error alike.
TEST(AdaptiveSampling, ZeroVarianceFurnaceStopsEveryPixelAtMinSpp) {
  for (const bool per_pixel : {true, false}) {
    RenderOverrides ov;
    (per_pixel ? ov.noise_threshold : ov.target_error) = 0.001f;
    ov.min_spp = 8;
    const AdaptiveFilm film = render_adaptive(white_furnace(), ov);
    for (const uint32_t n : film.samples) ASSERT_EQ(n, 8u) << per_pixel;
    for (float v : resolve_adaptive(film).rgb) ASSERT_NEAR(v, 1.0f, 1e-6);
    EXPECT_EQ(film.image_error, 0.0);
  }
}

TEST(AdaptiveSampling, HalfNoisySceneSpendsItsSamplesOnTheNoisyHalf) {
  RenderOverrides ov;
  ov.noise_threshold = 0.02f;
  const AdaptiveFilm film = render_adaptive(half_noisy("sobol"), ov);
  double left = 0, right = 0;
  for (uint32_t y = 0; y < film.height; ++y)
    for (uint32_t x = 0; x < film.width / 3; ++x) {
      EXPECT_EQ(film.samples[y * film.width + x], 16u) << x << "," << y;  // the sky: no variance
      left += film.samples[y * film.width + x];
      right += film.samples[y * film.width + film.width - 1 - x];
    }
  EXPECT_GT(right, 8.0 * left) << "mean spp: sky " << left / (film.height * (film.width / 3)) << ", lit surface "
                               << right / (film.height * (film.width / 3));
}

// With a threshold no noisy pixel meets, every pixel that takes all spp samples is the
// uniform render's pixel, bit for bit (its even and odd sums add up to the uniform sum).
TEST(AdaptiveSampling, APixelThatNeverStopsEqualsTheUniformRender) {
  for (const char* sampler : {"stochastic", "sobol"}) {
    RenderOverrides ov;
    ov.noise_threshold = 1e-6f;
    const AdaptiveFilm film = render_adaptive(half_noisy(sampler), ov);
    RenderStats stats;
    const Image uniform = render_cpu(test::scene_from(half_noisy(sampler)), 0, stats);
    const Image adaptive = resolve_adaptive(film);
    size_t full = 0;
    for (size_t i = 0; i < film.samples.size(); ++i) {
      if (film.samples[i] != 256u) continue;
      ++full;
      for (int c = 0; c < 3; ++c) ASSERT_EQ(adaptive.rgb[3 * i + c], uniform.rgb[3 * i + c]) << sampler << " " << i;
    }
    EXPECT_GT(full, film.samples.size() / 4) << sampler;  // most of the lit half
  }
}

// target_error renders every pixel to the same checkpoint, so the image is the uniform
// render at that spp bit for bit; the estimate there is below the target and at the
// checkpoint before it was not.
TEST(AdaptiveSampling, TargetErrorStopsAtTheFirstCheckpointBelowIt) {
  RenderOverrides ov;
  ov.width = 64;
  ov.height = 48;
  ov.spp = 1024;
  ov.target_error = 0.05f;
  ov.min_spp = 4;
  RenderStats stats;
  const std::string path = test::source_path("scenes/cornell-box-path.json");
  const AdaptiveFilm film = render_cpu_adaptive(load_scene(path, ov), 0, stats);
  const uint32_t reached = film.samples[0];
  for (const uint32_t n : film.samples) ASSERT_EQ(n, reached);
  EXPECT_GT(reached, 4u);
  EXPECT_LT(reached, 1024u);
  EXPECT_LT(film.image_error, 0.05);
  ov.target_error.reset();
  ov.min_spp.reset();
  ov.spp = reached;
  EXPECT_EQ(resolve_adaptive(film).rgb, render_cpu(load_scene(path, ov), 0, stats).rgb);
  ov.target_error = 0.05f;
  ov.min_spp = reached / 2;
  ov.spp = reached / 2;  // the checkpoint before: not yet below the target
  EXPECT_GE(render_cpu_adaptive(load_scene(path, ov), 0, stats).image_error, 0.05);
}

// Stopping a pixel on an estimate from its own samples biases it (optional stopping): a pixel
// whose first samples all missed a rare bright path has agreeing halves and stops low. The
// bias is measured here, not hidden: over every pixel and channel of the Cornell box (96x72,
// 64 spp at most, threshold 0.1, min 8, the same seed as the uniform render) the mean
// difference from the uniform render is z = -5.5 standard errors (docs/path.md), but under
// a tenth of the differences' RMS, so the image's error stays noise, not bias. An estimate
// dividing by the wrong count, or a pass skipping samples, fails both bounds.
TEST(AdaptiveSampling, AdaptiveRendersBiasIsUnderATenthOfItsNoise) {
  RenderOverrides ov;
  ov.width = 96;
  ov.height = 72;
  ov.spp = 64;
  const Scene uniform_scene = load_scene(test::source_path("scenes/cornell-box-path.json"), ov);
  RenderStats stats;
  const Image uniform = render_cpu(uniform_scene, 0, stats);
  ov.noise_threshold = 0.1f;
  ov.min_spp = 8;
  const AdaptiveFilm film =
      render_cpu_adaptive(load_scene(test::source_path("scenes/cornell-box-path.json"), ov), 0, stats);
  const Image adaptive = resolve_adaptive(film);
  double sum = 0, squares = 0, samples = 0;
  for (size_t i = 0; i < adaptive.rgb.size(); ++i) {
    const double d = double(adaptive.rgb[i]) - uniform.rgb[i];
    sum += d, squares += d * d;
  }
  for (const uint32_t n : film.samples) samples += n;
  const double count = static_cast<double>(adaptive.rgb.size());
  EXPECT_LT(samples, 0.9 * 64.0 * film.samples.size()) << "the threshold should stop pixels early";
  EXPECT_LT(std::abs(sum / count), 0.1 * std::sqrt(squares / count))
      << "bias " << sum / count << ", RMS difference " << std::sqrt(squares / count);
}

}  // namespace
}  // namespace tracer
