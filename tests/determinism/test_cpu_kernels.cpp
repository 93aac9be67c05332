// The CPU kernel's variants (tracer/render/cpu_kernel.h) give the same hits and the same
// images bit for bit: every instruction set this CPU runs and every feature set that holds
// a scene's features, against the baseline compilation in this test's own code and against
// every golden's hash.
#include <gtest/gtest.h>

#include <cstring>

#include "golden/golden_check.h"
#include "image/pixel_hash.h"
#include "kernel/accel/trace.h"
#include "render/cpu_kernel.h"
#include "render/render_adaptive.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"
#include "cpu_variants.h"
#include "test_util.h"

namespace tracer {
namespace {

using test::variants_for;

TEST(CpuKernels, TheBuildHasAGenericBaselineAndTheChoiceHoldsTheScene) {
  const std::vector<const CpuKernelVariant*> per_isa = cpu_kernels_per_isa(0u, true);
  ASSERT_FALSE(per_isa.empty());
  EXPECT_EQ(per_isa[0]->features, 0xffffffffu);
  for (uint32_t features : {0u, kFeatureTriangle | kFeatureLambert, kFeatureTextures | kFeatureSphere, 0x1fffu}) {
    const CpuKernelVariant& v = cpu_kernel_for(features);
    EXPECT_EQ(v.features & features, features) << cpu_kernel_name(v);
    EXPECT_EQ(cpu_kernel_for(features, true).features, 0xffffffffu);
  }
}

TEST(CpuKernels, EveryVariantGivesTheSameHitsInEveryShippedScene) {
  for (const auto& scene_path : test::shipped_scenes()) {
    const Scene scene = load_scene(scene_path.string(), RenderOverrides{});
    const SceneView view = scene.view();
    test::InputStream s{11};
    std::vector<Ray> rays;
    for (int i = 0; i < 4000; ++i) {
      const Vec3 d = {s.next() - 0.5f, s.next() - 0.5f, s.next() - 0.5f};
      if (length(d) > 0.0f) rays.push_back({scene.camera.origin, normalize(d)});
    }
    std::vector<Hit> reference(rays.size());
    std::vector<float> tmax(rays.size(), kInfinity), shadow_tmax(rays.size());
    std::vector<uint8_t> reference_any(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
      reference[i] = trace_closest(view, rays[i], kInfinity);
      shadow_tmax[i] = reference[i].prim != kNoHit ? reference[i].t * 1.5f : 1e3f;
      reference_any[i] = trace_any(view, rays[i], shadow_tmax[i]) ? 1 : 0;
    }
    for (const CpuKernelVariant* v : variants_for(view.features)) {
      std::vector<Hit> hits(rays.size());
      std::vector<uint8_t> any(rays.size());
      v->trace_closest(view, rays.data(), tmax.data(), rays.size(), hits.data());
      v->trace_any(view, rays.data(), shadow_tmax.data(), rays.size(), any.data());
      for (size_t i = 0; i < rays.size(); ++i) {
        ASSERT_EQ(std::memcmp(&hits[i], &reference[i], sizeof(Hit)), 0)
            << scene_path << ", " << cpu_kernel_name(*v) << ": ray " << i << " prim " << hits[i].prim << " against "
            << reference[i].prim;
        ASSERT_EQ(any[i], reference_any[i]) << scene_path << ", " << cpu_kernel_name(*v) << ": ray " << i;
      }
    }
  }
}

// Agreement, not correctness: it compares with the golden hashes, so once the goldens are
// regenerated it shows only that the variants agree with the render the update made; it is no
// evidence that the image is right (docs/mutation.md).
TEST(CpuKernels, EveryVariantRendersEveryGolden) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  size_t renders = 0;
  for (const GoldenEntry& entry : manifest.entries) {
    const Scene scene = load_scene(manifest.scene_path(entry), RenderOverrides{entry.options});
    for (const CpuKernelVariant* v : variants_for(scene.features)) {
      RenderStats stats;
      const uint32_t spp = scene.settings.spp;
      Image image;
      if (adaptive_render(scene.settings)) {
        const AdaptiveFilm film = render_cpu_adaptive(scene, 0, stats, {}, v);
        image = entry.image == GoldenImage::SampleMap ? adaptive_sample_map(film) : resolve_adaptive(film);
      } else {
        image = resolve_film(render_cpu_film(scene, {0, spp}, 0, stats, {}, v), spp);
      }
      EXPECT_EQ(pixel_hash(image), entry.hash) << entry.name << " with " << cpu_kernel_name(*v);
      ++renders;
    }
  }
  std::printf("%zu renders of %zu goldens\n", renders, manifest.entries.size());
}

}  // namespace
}  // namespace tracer
