// An adaptive render's stopped pixels depend on exact integer sums only, so its image and
// its sample map are the same bit for bit for any thread count and every structure.
#include <gtest/gtest.h>

#include "render/render_adaptive.h"
#include "test_util.h"

namespace tracer {
namespace {

AdaptiveFilm render(const std::string& scene, int threads, AccelKind accel) {
  RenderOverrides ov;
  ov.noise_threshold = 0.05f;
  ov.spp = 64;
  ov.min_spp = 4;
  ov.width = 64;
  ov.height = 48;
  ov.accel = accel;
  RenderStats stats;
  return render_cpu_adaptive(load_scene(test::source_path(scene), ov), threads, stats);
}

TEST(AdaptiveDeterminism, SameImageAndSampleMapForAnyThreadsAndStructure) {
  for (const char* scene : {"scenes/cornell-box-path.json", "scenes/showcase.json"}) {
    const AdaptiveFilm reference = render(scene, 1, AccelKind::Bvh);
    const Image image = resolve_adaptive(reference);
    uint32_t lowest = 64, highest = 0;
    for (const uint32_t n : reference.samples) lowest = std::min(lowest, n), highest = std::max(highest, n);
    EXPECT_LT(lowest, highest) << scene << ": the threshold should stop some pixels and not others";
    for (const int threads : {2, 7})
      for (const AccelKind accel : {AccelKind::Bvh, AccelKind::Kdtree, AccelKind::Grid, AccelKind::Lbvh}) {
        const AdaptiveFilm other = render(scene, threads, accel);
        EXPECT_EQ(other.samples, reference.samples) << scene << " threads " << threads;
        EXPECT_EQ(resolve_adaptive(other).rgb, image.rgb) << scene << " threads " << threads;
      }
  }
}

}  // namespace
}  // namespace tracer
