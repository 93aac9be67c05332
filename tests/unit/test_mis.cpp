// Multiple importance sampling's power heuristic (Veach 1997, section 9.2.4, beta = 2):
// w_a = p_a^2 / (p_a^2 + p_b^2). At unequal densities it differs from the balance heuristic
// p_a / (p_a + p_b), which is unbiased too: no convergence test can tell them apart, so the
// weights themselves are checked here (ci/mutants.txt: mis-balance-heuristic).
#include <gtest/gtest.h>

#include "kernel/shading/sampling.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(Mis, PowerHeuristicWeighsByTheSquaredDensities) {
  EXPECT_EQ(power_heuristic(1.0f, 3.0f), 0.1f);  // 1 / (1 + 9); the balance heuristic gives 1/4
  EXPECT_EQ(power_heuristic(3.0f, 1.0f), 0.9f);
  EXPECT_EQ(power_heuristic(2.0f, 2.0f), 0.5f);
  EXPECT_EQ(power_heuristic(5.0f, 0.0f), 1.0f);  // the other strategy cannot draw it
  EXPECT_EQ(power_heuristic(0.0f, 5.0f), 0.0f);
  EXPECT_EQ(power_heuristic(0.0f, 0.0f), 0.0f);  // neither can: no weight, never NaN
}

// The two strategies' weights of one sample sum to 1, so MIS neither adds nor loses light.
TEST(Mis, TheTwoWeightsOfASampleSumToOne) {
  for (const float a : {1e-6f, 0.01f, 0.3f, 1.0f, 7.0f, 1e4f})
    for (const float b : {1e-6f, 0.02f, 0.5f, 2.0f, 30.0f, 1e5f})
      EXPECT_NEAR(power_heuristic(a, b) + power_heuristic(b, a), 1.0f, 1e-6f) << a << " " << b;
}

// Densities whose squares overflow float (a light under 5e-20 sr: a density past 1.8e19) gave
// inf / inf = NaN, and most samples of such a light NaN. The weight comes from their ratio now,
// the same weight, and where the squares fit it is the same float as before.
TEST(Mis, DensitiesPastTheSquaresRangeKeepTheirWeight) {
  EXPECT_EQ(power_heuristic(4e19f, 1.0f), 1.0f);
  EXPECT_TRUE(power_heuristic(1.0f, 4e19f) >= 0.0f && power_heuristic(1.0f, 4e19f) < 1e-38f);  // (1 / 4e19)^2
  EXPECT_NEAR(power_heuristic(3e19f, 4e19f), 9.0f / 25.0f, 1e-6f);
  EXPECT_NEAR(power_heuristic(4e19f, 3e19f), 16.0f / 25.0f, 1e-6f);
  EXPECT_NEAR(power_heuristic(3e19f, 4e19f) + power_heuristic(4e19f, 3e19f), 1.0f, 1e-6f);
  EXPECT_EQ(power_heuristic(1e19f, 1e19f), 0.5f);  // the squares still fit: a^2 / (a^2 + b^2)
  EXPECT_EQ(power_heuristic(3.0f, 1.0f), 0.9f);
}

// A lamp of 3e-20 sr (a sphere of radius 1e-10 at distance 1) lighting a plane: most of its
// samples were NaN under area and solid-angle sampling alike; none is now.
TEST(Mis, ASmallFarLightGivesNoNaNSample) {
  const std::string scene = R"({"format": "tracer-scene/1", "camera": {"from": [0, 2, 3], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 6}, "render": {"integrator": "path", "spp": 16, "sampler": "sobol"},
    "materials": {"floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]},
                  "lamp": {"type": "emissive", "radiance": [1e6, 1e6, 1e6]}},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
               {"type": "sphere", "center": [0, 1, 0], "radius": 1e-10, "material": "lamp"}]})";
  for (const LightSampling sampling : {LightSampling::Area, LightSampling::SolidAngle}) {
    RenderOverrides o;
    o.light_sampling = sampling;
    RenderStats stats;
    render_cpu(test::scene_from(scene, o), 1, stats);
    EXPECT_EQ(stats.nonfinite_samples, 0u) << static_cast<int>(sampling);
  }
}

}  // namespace
}  // namespace tracer
