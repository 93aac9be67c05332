// docs/determinism.md rule 4 made real: every acceleration structure returns the same closest hit,
// bit for bit, and the same any-hit answer. Ray by ray over every shipped scene, with rays
// aimed at shared edges and vertices (ties at equal t) and along cell boundaries; and image
// by image, the representative goldens (test_util.h) rendered with every structure hash to
// theirs.
#include <gtest/gtest.h>

#include <cstring>

#include "golden/golden_check.h"
#include "kernel/accel/trace.h"
#include "options/enum_names.h"
#include "probe_rays.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"
#include "test_util.h"

namespace tracer {
namespace {

const std::vector<std::string>& structures() { return accepted_scene_types().at("accel"); }

TEST(AccelIdentity, EveryStructureGivesTheSameHitsInEveryShippedScene) {
  int scenes = 0;
  for (const auto& scene_path : test::shipped_scenes()) {
    ++scenes;
    const std::string path = scene_path.string();
    std::vector<Scene> built;
    for (const std::string& accel : structures()) {
      RenderOverrides ov;
      ov.accel = parse_enum<AccelKind>(accel, "accel");
      built.push_back(load_scene(path, ov));
    }
    ASSERT_EQ(structures()[0], "bvh");
    if (!built[0].bounded.empty()) {
      ASSERT_GT(built[0].wide_nodes.size(), 0u) << path << ": bvh has no wide tree";
    }
    SceneView binary = built[0].view();
    binary.wide_node_count = 0;
    const std::vector<Ray> rays = test::probe_rays(built[0]);
    size_t hits = 0;
    for (const Ray& ray : rays) {
      const Hit reference = trace_closest(built[0].view(), ray, kInfinity);
      hits += reference.prim != kNoHit;
      const float shadow_tmax = reference.prim != kNoHit ? reference.t * 1.5f : 1e3f;
      const bool reference_any = trace_any(built[0].view(), ray, shadow_tmax);
      for (size_t k = 1; k < built.size(); ++k) {
        const Hit h = trace_closest(built[k].view(), ray, kInfinity);
        ASSERT_EQ(std::memcmp(&h, &reference, sizeof(Hit)), 0)
            << path << ", " << structures()[k] << ": prim " << h.prim << " t " << h.t << " against bvh's prim "
            << reference.prim << " t " << reference.t;
        ASSERT_EQ(trace_any(built[k].view(), ray, shadow_tmax), reference_any) << path << ", " << structures()[k];
      }
      // bvh's own binary tree, walked two children at a time as the GPU walks it
      const Hit h = trace_closest(binary, ray, kInfinity);
      ASSERT_EQ(std::memcmp(&h, &reference, sizeof(Hit)), 0) << path << ", bvh binary: prim " << h.prim;
      ASSERT_EQ(trace_any(binary, ray, shadow_tmax), reference_any) << path << ", bvh binary";
    }
    EXPECT_GT(hits, rays.size() / 10) << path;
  }
  EXPECT_GE(scenes, 10);
}

// A grid whose cell boundaries fall on the edges of a tiled floor, probed by rays along
// those boundaries and through the shared corners.
TEST(AccelIdentity, HitsOnCellBoundariesAndStraddlingPrimitives) {
  std::string shapes;
  for (int z = 0; z < 8; ++z)
    for (int x = 0; x < 8; ++x)
      shapes += R"({"type": "quad", "corner": [)" + std::to_string(x) + ", 0, " + std::to_string(z) +
                R"(], "u": [0, 0, 1], "v": [1, 0, 0], "material": "m"},)";
  shapes += R"({"type": "box", "min": [1.5, 0, 1.5], "max": [6.5, 2, 2.5], "material": "m"},
               {"type": "sphere", "center": [4, 1, 5], "radius": 2.5, "material": "m"})";
  const std::string json = R"({"format": "tracer-scene/1", "camera": {"from": [4, 6, -6], "to": [4, 0, 4], "vfov": 50},
    "film": {"width": 8, "height": 8}, "render": {"grid_resolution": 8},
    "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}}, "shapes": [)" +
                           shapes + "]}";
  std::vector<Scene> built;
  for (const std::string& accel : structures()) {
    RenderOverrides ov;
    ov.accel = parse_enum<AccelKind>(accel, "accel");
    built.push_back(test::scene_from(json, ov));
  }
  std::vector<Ray> rays;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const Vec3 corner = {float(i), 0.0f, float(j)};
      rays.push_back({corner + Vec3{0, 3, 0}, {0, -1, 0}});                       // straight down onto a shared corner
      rays.push_back({corner + Vec3{0.5f, 3, 0}, normalize(Vec3{0, -1, 0.3f})});  // down along a boundary plane
      rays.push_back({Vec3{-1, 0.5f, float(j)}, {1, 0, 0}});                      // along a boundary, through the box
    }
  for (const Ray& ray : rays) {
    const Hit reference = trace_closest(built[0].view(), ray, kInfinity);
    for (size_t k = 1; k < built.size(); ++k) {
      const Hit h = trace_closest(built[k].view(), ray, kInfinity);
      ASSERT_EQ(std::memcmp(&h, &reference, sizeof(Hit)), 0)
          << structures()[k] << ": prim " << h.prim << " against " << reference.prim;
    }
  }
  EXPECT_GT(built[4].grid.n[0], 1u) << "the grid test needs cells";
}

// Whole images: a golden of each integrator and kind of scene rendered with each structure
// hashes to the golden (the hits themselves are compared ray by ray above, on every shipped
// scene; every golden is rendered with its own structure by the golden label).
// Agreement, not correctness: it compares with the golden hashes, so once the goldens are
// regenerated it shows only that the structures agree with the render the update made; it is no
// evidence that the image is right (docs/mutation.md).
TEST(AccelIdentity, RepresentativeGoldensWithEveryStructure) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  size_t goldens = 0;
  for (const GoldenEntry& entry : manifest.entries) {
    if (!test::is_representative_golden(entry.name)) continue;
    ++goldens;
    for (const std::string& accel : structures()) {
      GoldenEntry e = entry;
      e.options.accel = parse_enum<AccelKind>(accel, "accel");
      EXPECT_EQ(render_golden(manifest, e, 0).hash, entry.hash) << entry.name << " with " << accel;
    }
  }
  EXPECT_EQ(goldens, test::representative_goldens().size()) << "a representative golden is not in the manifest";
}

}  // namespace
}  // namespace tracer
