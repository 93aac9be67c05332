// Multiple importance sampling's power heuristic (Veach 1997, section 9.2.4, beta = 2):
// w_a = p_a^2 / (p_a^2 + p_b^2). At unequal densities it differs from the balance heuristic
// p_a / (p_a + p_b), which is unbiased too: no convergence test can tell them apart, so the
// weights themselves are checked here (ci/mutants.txt: mis-balance-heuristic).
#include <gtest/gtest.h>

#include "kernel/shading/sampling.h"

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

}  // namespace
}  // namespace tracer
