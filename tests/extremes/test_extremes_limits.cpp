// Limits of brightness, sampling and image size: emitters of 1e30 are reported as film
// overflow, never as NaN; max_depth 0 shows only what emits; 1x1 and 1x4096 images render;
// and every golden render has zero NaN/inf and zero overflowing samples.
#include <gtest/gtest.h>

#include <cmath>

#include "golden/golden_check.h"
#include "io/output_batch.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

std::string lamp_scene(const std::string& radiance, const std::string& integrator, uint32_t max_depth, uint32_t w,
                       uint32_t h) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 1, 3], "to": [0, 0.5, 0], "vfov": 60},
    "film": {"width": )" +
         std::to_string(w) + R"(, "height": )" + std::to_string(h) + R"(},
    "render": {"integrator": ")" +
         integrator + R"(", "spp": 4, "sampler": "stochastic", "max_depth": )" + std::to_string(max_depth) + R"(},
    "materials": {"lamp": {"type": "emissive", "radiance": [)" +
         radiance + ", " + radiance + ", " + radiance + R"(]},
                  "floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.4, "material": "lamp"},
               {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})";
}

TEST(ExtremesLimits, EmitterOf1e30IsReportedAsOverflowNotNaN) {
  for (const char* integrator : {"path", "whitted"}) {
    RenderStats stats;
    const Image img = render_cpu(test::scene_from(lamp_scene("1e30", integrator, 4, 24, 16)), 0, stats);
    EXPECT_EQ(stats.nonfinite_samples, 0u) << integrator;
    if (std::string(integrator) == "path") {
      EXPECT_GT(stats.overflow_samples, 0u) << integrator;
    }
    for (float v : img.rgb) EXPECT_TRUE(std::isfinite(v)) << integrator;
  }
}

// With max_depth 0 the path integrator adds only the emission the camera ray sees: one
// centre sample per pixel reads the lamp's 2 or exactly 0, where max_depth 1 lights the floor.
TEST(ExtremesLimits, MaxDepthZeroShowsOnlyEmitters) {
  RenderOverrides ov;
  ov.sampler = SamplerKind::Center;
  ov.spp = 1;
  for (const uint32_t depth : {0u, 1u, 64u}) {
    RenderStats stats;
    const Image img = render_cpu(test::scene_from(lamp_scene("2", "path", depth, 24, 16), ov), 0, stats);
    EXPECT_EQ(stats.nonfinite_samples + stats.overflow_samples, 0u) << "max_depth " << depth;
    int lamp = 0, dark = 0;
    for (float v : img.rgb) lamp += v == 2.0f, dark += v == 0.0f;
    EXPECT_GT(lamp, 0) << "max_depth " << depth;
    if (depth == 0) {
      EXPECT_EQ(lamp + dark, int(img.rgb.size())) << "only emitters at max_depth 0";
    } else
      EXPECT_LT(lamp + dark, int(img.rgb.size())) << "the floor is lit at max_depth " << depth;
  }
}

// A pixel's film sum holds below 2^62 units of 2^-32, a radiance total below 2^30: with a
// sky of 1024 (2^42 units a sample) the first 2^20 - 1 samples fit and every later one is
// counted as overflow, exactly; `tracer render` says so in its warning.
TEST(ExtremesLimits, FilmCapacityIsReachedAndCountedExactly) {
  const uint32_t spp = 1u << 21;
  const std::string json = R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 1], "to": [0, 0, 0], "vfov": 30},
    "film": {"width": 1, "height": 1}, "render": {"integrator": "path", "spp": )" +
                           std::to_string(spp) + R"(, "sampler": "stochastic"},
    "background": {"type": "constant", "radiance": [1024, 1024, 1024]}, "materials": {}, "shapes": []})";
  RenderStats stats;
  const Image img = render_cpu(test::scene_from(json), 0, stats);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  EXPECT_EQ(stats.overflow_samples, spp - ((1u << 20) - 1));
  EXPECT_EQ(img.rgb[0], static_cast<float>(1024.0 * ((1u << 20) - 1) / spp));  // rejected samples count as 0
  const auto dir = test::temp_dir("film-capacity");
  write_file_atomically((dir / "bright.json").string(), json);
  std::string output;
  ASSERT_EQ(
      test::run_tracer("render " + (dir / "bright.json").string() + " -o " + (dir / "bright.exr").string() + " --quiet",
                       &output),
      0)
      << output;
  EXPECT_NE(
      output.find("warning: " + std::to_string(spp - ((1u << 20) - 1)) + " samples were left out (film overflow)"),
      std::string::npos)
      << output;
  std::filesystem::remove_all(dir);
}

TEST(ExtremesLimits, OneByOneAndOneByFourThousandImages) {
  for (const auto& [w, h] : {std::pair{1u, 1u}, std::pair{1u, 4096u}, std::pair{4096u, 1u}}) {
    RenderStats stats;
    const Image img = render_cpu(test::scene_from(lamp_scene("2", "path", 4, w, h)), 0, stats);
    ASSERT_EQ(img.rgb.size(), size_t(3) * w * h);
    EXPECT_EQ(stats.nonfinite_samples + stats.overflow_samples, 0u) << w << "x" << h;
    for (float v : img.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << w << "x" << h;
  }
}

// The NaN/inf counter over every golden render reads zero (and no sample overflows).
TEST(ExtremesLimits, EveryGoldenRenderHasNoNaNInfOrOverflow) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  ASSERT_GE(manifest.entries.size(), 30u);
  for (const GoldenEntry& entry : manifest.entries) {
    const GoldenRender r = render_golden(manifest, entry, 0);
    EXPECT_EQ(r.nonfinite_samples, 0u) << entry.name;
    EXPECT_EQ(r.overflow_samples, 0u) << entry.name;
    size_t bad = 0;
    for (float v : r.image.rgb) bad += !std::isfinite(v);
    EXPECT_EQ(bad, 0u) << entry.name;
  }
}

}  // namespace
}  // namespace tracer
