// The coverage rule: every shape, material, light, background, integrator, sampler,
// accelerator, texture and transform type that the scene loader accepts is drawn by at least one golden of
// golden/manifest.json. A type added to the loader without a golden fails here, by name.
#include <gtest/gtest.h>

#include "golden/golden_manifest.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(GoldenCoverage, EveryAcceptedTypeAppearsInAGolden) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  ASSERT_FALSE(manifest.entries.empty());
  std::set<std::string> used;
  for (const GoldenEntry& e : manifest.entries) {
    const Scene scene = load_scene(manifest.scene_path(e), RenderOverrides{e.options});
    used.insert(scene.report.used_types.begin(), scene.report.used_types.end());
  }
  std::string missing;
  size_t accepted = 0;
  for (const auto& [category, names] : accepted_scene_types())
    for (const std::string& name : names) {
      ++accepted;
      if (!used.count(category + ":" + name)) missing += " " + category + ":" + name;
    }
  EXPECT_TRUE(missing.empty()) << "types the loader accepts that no golden draws:" << missing;
  EXPECT_GE(accepted, 24u) << "the loader accepted 24 types when this test was written";
}

TEST(GoldenCoverage, UsedTypesAreRecordedPerCategory) {
  const Scene scene = test::scene_from(R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40}, "film": {"width": 4, "height": 4},
    "render": {"sampler": "grid", "spp": 4, "integrator": "depth", "accel": "none"},
    "background": {"type": "gradient", "zenith": [0, 0, 1], "horizon": [1, 1, 1]},
    "materials": {"m": {"type": "metal", "albedo": [1, 1, 1]}, "unused": {"type": "phong", "diffuse": [1, 1, 1]}},
    "lights": [{"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]}],
    "shapes": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": "m"}]})");
  const std::set<std::string> expected = {"accel:none",     "background:gradient", "integrator:depth", "light:point",
                                          "material:metal", "sampler:grid",        "shape:box"};
  EXPECT_EQ(scene.report.used_types, expected) << "a material no shape uses is not drawn, so it is not counted";
}

}  // namespace
}  // namespace tracer
