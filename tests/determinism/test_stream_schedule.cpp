// The stream schedule (kernel/integrator/stream.h, render/render_stream.cpp) renders every
// golden to its hash on every CPU kernel variant, the representative goldens (test_util.h) on
// every accelerator, and a golden of each
// integrator with any thread count and stream widths that split a pixel's samples across batches. The schedule
// changes the order in which rays are traced, never a sample's arithmetic.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cpu_variants.h"
#include "golden/golden_check.h"
#include "image/pixel_hash.h"
#include "render/cpu_kernel.h"
#include "render/render_adaptive.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"
#include "test_util.h"

namespace tracer {
namespace {

using test::variants_for;

Scene stream_scene(const GoldenManifest& manifest, const GoldenEntry& entry, uint32_t width,
                   std::optional<AccelKind> accel = {}, StreamOrder order = StreamOrder::Queue) {
  RenderOverrides overrides{entry.options};
  overrides.schedule = Schedule::Stream;
  overrides.stream_width = width;
  overrides.stream_order = order;
  if (accel) overrides.accel = *accel;
  return load_scene(manifest.scene_path(entry), overrides);
}

Image render_golden_image(const Scene& scene, const GoldenEntry& entry, int threads, RenderStats& stats,
                          const CpuKernelVariant* v = nullptr) {
  if (adaptive_render(scene.settings)) {
    const AdaptiveFilm film = render_cpu_adaptive(scene, threads, stats, {}, v);
    return entry.image == GoldenImage::SampleMap ? adaptive_sample_map(film) : resolve_adaptive(film);
  }
  return resolve_film(render_cpu_film(scene, {0, scene.settings.spp}, threads, stats, {}, v), scene.settings.spp);
}

// Agreement with the goldens, as CpuKernels.EveryVariantRendersEveryGolden (docs/mutation.md):
// a stream bug that changes any sample's radiance, its film order or a pixel's count shows.
TEST(StreamSchedule, EveryVariantRendersEveryGolden) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  size_t renders = 0;
  for (const GoldenEntry& entry : manifest.entries) {
    const Scene scene = stream_scene(manifest, entry, 1000);  // 1000: not a multiple of any spp
    for (const CpuKernelVariant* v : variants_for(scene.features)) {
      RenderStats stats;
      EXPECT_EQ(pixel_hash(render_golden_image(scene, entry, 1, stats, v)), entry.hash)
          << entry.name << " with " << cpu_kernel_name(*v);
      EXPECT_GT(stats.stream.batches, 0u) << entry.name;
      ++renders;
    }
  }
  std::printf("%zu stream renders of %zu goldens\n", renders, manifest.entries.size());
}

// Each accelerator's trace stages (the structures' hits are compared ray by ray in
// AccelIdentity, every golden's stream render in the test above).
TEST(StreamSchedule, EveryAcceleratorRendersTheRepresentativeGoldens) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  size_t goldens = 0;
  for (const GoldenEntry& entry : manifest.entries) {
    if (!test::is_representative_golden(entry.name)) continue;
    ++goldens;
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Kdtree, AccelKind::Grid, AccelKind::Lbvh}) {
      const Scene scene = stream_scene(manifest, entry, 1000, accel);
      RenderStats stats;
      EXPECT_EQ(pixel_hash(render_golden_image(scene, entry, 1, stats)), entry.hash)
          << entry.name << " with accel " << static_cast<int>(accel);
    }
  }
  EXPECT_EQ(goldens, test::representative_goldens().size()) << "a representative golden is not in the manifest";
}

// render.stream_order sorted puts the trace and shadow queues in their rays' key order before
// each wave traces them: every golden renders to its hash, on one thread and with batches that
// split pixels on two. A sort that lost, doubled or swapped a queue's entries would leave a
// state untraced or traced twice and change pixels.
TEST(StreamSchedule, SortedQueuesRenderEveryGolden) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  for (const GoldenEntry& entry : manifest.entries) {
    const Scene scene = stream_scene(manifest, entry, 1000, {}, StreamOrder::Sorted);
    RenderStats stats;
    EXPECT_EQ(pixel_hash(render_golden_image(scene, entry, 1, stats)), entry.hash) << entry.name;
    if (entry.name != "cornell-box" && entry.name != "cornell-box-path") continue;
    const Scene split = stream_scene(manifest, entry, 97, {}, StreamOrder::Sorted);
    EXPECT_EQ(pixel_hash(render_golden_image(split, entry, 2, stats)), entry.hash) << entry.name << ", width 97";
  }
}

// The tests above run one thread: the stream's stages meet at a barrier several times per wave,
// and under ctest -j2 on 2 cores a second test's threads made those barriers cost 10-20x (105 s
// for the accelerator test on a fresh machine). Here, thread counts and widths that split
// pixels across batches, on a golden of each integrator (Whitted, path, adaptive).
TEST(StreamSchedule, AnyThreadCountAndWidthRendersTheGolden) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  for (const GoldenEntry& entry : manifest.entries) {
    if (entry.name != "cornell-box" && entry.name != "cornell-box-path" && entry.name != "cornell-box-adaptive")
      continue;
    // 97: batches that split pixels; 7 threads on 2 cores: oversubscribed (its barriers are
    // slow, so it runs at the wider widths, with fewer batches).
    const std::pair<uint32_t, int> cases[] = {{97u, 1}, {97u, 2}, {1000u, 7}, {1u << 18, 2}, {1u << 18, 7}};
    for (const auto& [width, threads] : cases) {
      const Scene scene = stream_scene(manifest, entry, width);
      RenderStats stats;
      EXPECT_EQ(pixel_hash(render_golden_image(scene, entry, threads, stats)), entry.hash)
          << entry.name << ", width " << width << ", " << threads << " threads";
    }
  }
}

TEST(StreamSchedule, ReportsItsQueuesAndMemory) {
  RenderOverrides overrides;
  overrides.schedule = Schedule::Stream;
  overrides.stream_width = 4096u;
  overrides.width = 32u;
  overrides.height = 24u;
  overrides.spp = 8u;
  const Scene scene = load_scene(std::string(TRACER_SOURCE_DIR) + "/scenes/cornell-box-path.json", overrides);
  RenderStats stats;
  render_cpu(scene, 2, stats);
  EXPECT_EQ(stats.stream.batches, (32u * 24u * 8u + 4095u) / 4096u);
  EXPECT_EQ(stats.stream.largest_queue, 4096u);
  EXPECT_GT(stats.stream.waves, stats.stream.batches);  // a path takes more than one bounce
  EXPECT_EQ(stats.stream.shadow_rays, stats.rays.shadow);
  EXPECT_EQ(stats.stream.state_bytes, stats.stream.bytes_per_state * 4096u);
  overrides.stream_order = StreamOrder::Sorted;  // the sort's keys and entries, double-buffered
  RenderStats sorted;
  render_cpu(load_scene(std::string(TRACER_SOURCE_DIR) + "/scenes/cornell-box-path.json", overrides), 2, sorted);
  EXPECT_EQ(sorted.stream.bytes_per_state, stats.stream.bytes_per_state + 4 * sizeof(uint32_t));
}

}  // namespace
}  // namespace tracer

namespace tracer {
namespace {

// Bad widths exit 2 with the key named and nothing written.
TEST(StreamSchedule, RefusesBadWidthsAndWritesNothing) {
  const auto dir = test::temp_dir("stream-refusals");
  const std::string scene = std::string(TRACER_SOURCE_DIR) + "/scenes/cornell-box-path.json";
  const std::string out = (dir / "x.exr").string();
  const std::pair<std::string, std::string> cases[] = {
      {"--stream-width 64", "needs schedule stream"},
      {"--schedule stream --stream-width 0", "expected 1 to 16777216"},
      {"--schedule stream --stream-width 16777217", "expected 1 to 16777216"},
      {"--schedule stream --stream-width 1e3", "--stream-width"},
      {"--schedule streams", "megakernel or stream"},
      {"--stream-order sorted", "needs schedule stream"},
      {"--schedule stream --stream-order random", "unknown stream order"},
  };
  for (const auto& [flags, message] : cases) {
    std::string output;
    EXPECT_EQ(test::run_tracer("render " + scene + " " + flags + " -o " + out, &output), 2) << flags;
    EXPECT_NE(output.find(message), std::string::npos) << flags << ": " << output;
    EXPECT_FALSE(std::filesystem::exists(out)) << flags;
  }
  std::filesystem::remove_all(dir);
}

// The stream's counters reach --stats.
TEST(StreamSchedule, StatsReportTheStream) {
  const auto dir = test::temp_dir("stream-stats");
  std::string output;
  ASSERT_EQ(test::run_tracer("render " + std::string(TRACER_SOURCE_DIR) +
                                 "/scenes/cornell-box.json --schedule stream --stream-width 500 --width 20 "
                                 "--height 10 --quiet -o " +
                                 (dir / "x.png").string() + " --stats " + (dir / "s.json").string(),
                             &output),
            0)
      << output;
  std::ifstream in(dir / "s.json");
  const nlohmann::json stats = nlohmann::json::parse(in);
  EXPECT_EQ(stats["stream"]["width"], 500);
  EXPECT_EQ(stats["stream"]["order"], "queue");
  EXPECT_EQ(stats["stream"]["batches"], (200 * stats["spp"].get<int>() + 499) / 500);
  EXPECT_GT(stats["stream"]["bytes_per_state"].get<int>(), 100);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
