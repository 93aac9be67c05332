// An adaptive render's stopped pixels depend on exact integer sums only, so its image and
// its sample map are the same bit for bit for any thread count, every structure and every
// CPU kernel variant (instruction set and feature set) this machine runs.
#include <gtest/gtest.h>

#include "render/cpu_kernel.h"
#include "render/render_adaptive.h"
#include "test_util.h"

namespace tracer {
namespace {

AdaptiveFilm render(const std::string& scene, int threads, AccelKind accel, const CpuKernelVariant* kernel = nullptr) {
  RenderOverrides ov;
  ov.noise_threshold = 0.05f;
  ov.spp = 64;
  ov.min_spp = 4;
  ov.width = 64;
  ov.height = 48;
  ov.accel = accel;
  RenderStats stats;
  return render_cpu_adaptive(load_scene(test::source_path(scene), ov), threads, stats, {}, kernel);
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
    const uint32_t features = load_scene(test::source_path(scene), RenderOverrides{}).features;
    for (const CpuKernelVariant* generic : cpu_kernels_per_isa(features, true))
      for (const CpuKernelVariant* v : cpu_kernel_variants()) {
        if (v->isa != std::string(generic->isa) || (v->features & features) != features) continue;
        const AdaptiveFilm other = render(scene, 2, AccelKind::Bvh, v);
        EXPECT_EQ(other.samples, reference.samples) << scene << " " << cpu_kernel_name(*v);
        EXPECT_EQ(resolve_adaptive(other).rgb, image.rgb) << scene << " " << cpu_kernel_name(*v);
      }
  }
}

}  // namespace
}  // namespace tracer
