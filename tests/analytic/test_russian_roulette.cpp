// Russian roulette's survival rule against its closed form. Inside a closed Lambert sphere of
// albedo a with no light, every BSDF sample multiplies the throughput by exactly a, so the
// throughput after vertex k is a^(k+1) and the first vertex's is a. With roulette from
// rr_depth r on, the path survives vertex r - 1 with q = a^r / a = a^(r-1) and every later
// one with q = a (its throughput, a after each division, times a, over a). The number K of
// secondary rays of a sample then has P(K >= k) = 1 for k < r and a^(k-1) for r <= k <= D
// (max_depth), a distribution whose mean and variance the test computes exactly; the old
// rule, q = min(throughput, 0.95), survives vertex r - 1 with a^r instead and fails it.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

struct Moments {
  double mean, variance;
};

// E[K] = sum_k P(K >= k), E[K^2] = sum_k (2k - 1) P(K >= k).
Moments secondary_rays_per_sample(double a, uint32_t rr_depth, uint32_t max_depth) {
  double mean = 0.0, second = 0.0;
  for (uint32_t k = 1; k <= max_depth; ++k) {
    const double at_least_k = k < rr_depth ? 1.0 : std::pow(a, k - 1.0);
    mean += at_least_k;
    second += (2.0 * k - 1.0) * at_least_k;
  }
  return {mean, second - mean * mean};
}

void expect_survival(float albedo, uint32_t rr_depth) {
  constexpr uint32_t kMaxDepth = 8, kWidth = 40, kHeight = 40, kSpp = 16;
  const std::string a = std::to_string(albedo);
  RenderOverrides ov;
  ov.rr_depth = rr_depth;
  ov.max_depth = kMaxDepth;
  ov.spp = kSpp;
  RenderStats stats;
  render_cpu(
      test::scene_from(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 0], "to": [0, 0, 1], "vfov": 70},
    "film": {"width": )" + std::to_string(kWidth) +
                           R"(, "height": )" + std::to_string(kHeight) + R"(},
    "render": {"integrator": "path", "sampler": "stochastic"},
    "materials": {"shell": {"type": "lambert", "albedo": [)" +
                           a + ", " + a + ", " + a + R"(]}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "shell"}]})",
                       ov),
      0, stats);
  const double samples = double(kWidth) * kHeight * kSpp;
  const Moments k = secondary_rays_per_sample(albedo, rr_depth, kMaxDepth);
  const double measured = double(stats.rays.secondary) / samples;
  EXPECT_NEAR(measured, k.mean, 5.0 * std::sqrt(k.variance / samples))
      << "albedo " << albedo << ", rr_depth " << rr_depth;
}

TEST(RussianRoulette, SurvivalIsTheThroughputRelativeToTheFirstVertex) { expect_survival(0.5f, 3); }
TEST(RussianRoulette, SurvivalOfADarkerSphere) { expect_survival(0.25f, 3); }
TEST(RussianRoulette, SurvivalFromALaterDepth) { expect_survival(0.5f, 5); }
// From the first bounce on, the first vertex's own roulette always survives (q = a / a).
TEST(RussianRoulette, SurvivalFromTheFirstBounce) { expect_survival(0.5f, 1); }

}  // namespace
}  // namespace tracer
