// The GPU's walk of the binary BVH through pair records (kernel/accel/bvh_pair_node.h,
// traverse_bvh_pairs.h), run here on the CPU from the same template code: it returns the
// node walk's hits, bit for bit, ties included, in every shipped scene under bvh and lbvh, for
// and in generated meshes of every kind, for the full code and for the trace variant that walks
// it; and the builder refuses a tree deeper than the walk's stack or pointing outside its arrays.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "accel/bvh_pairs_builder.h"
#include "bench/mesh_generators.h"
#include "io/input_error.h"
#include "kernel/accel/trace.h"
#include "kernel/accel/trace_variants.h"
#include "probe_rays.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"
#include "test_util.h"

namespace tracer {
namespace {

// `view` walking the pair records of `pairs`.
SceneView with_pairs(SceneView view, const BvhPairs& pairs) {
  view.wide_node_count = 0;
  view.bvh_pairs = pairs.nodes.data();
  view.bvh_pair_triangles = pairs.triangles.data();
  view.bvh_pair_count = static_cast<uint32_t>(pairs.nodes.size());
  return view;
}

constexpr int kBvhTriangles =
    trace_variant_for(kTraceBvhPairs | kFeatureTriangle | kFeaturePlane | kTraceWatertight);

void expect_same_hits(const std::string& what, const SceneView& nodes, const SceneView& pairs,
                      const std::vector<Ray>& rays, bool variant) {
  for (const Ray& ray : rays) {
    const Hit reference = trace_closest(nodes, ray, kInfinity);
    const Hit h = variant ? trace_closest<kTraceVariants[kBvhTriangles].code>(pairs, ray, kInfinity)
                          : trace_closest(pairs, ray, kInfinity);
    ASSERT_EQ(std::memcmp(&h, &reference, sizeof(Hit)), 0)
        << what << ": prim " << h.prim << " t " << h.t << " against the node walk's prim " << reference.prim << " t "
        << reference.t;
    for (const float tmax : {reference.prim != kNoHit ? reference.t * 1.5f : 1e3f, reference.t}) {
      if (reference.prim == kNoHit && tmax == reference.t) continue;
      const bool any =
          variant ? trace_any<kTraceVariants[kBvhTriangles].code>(pairs, ray, tmax) : trace_any(pairs, ray, tmax);
      ASSERT_EQ(any, trace_any(nodes, ray, tmax)) << what << ", any hit before " << tmax;
    }
  }
}

// The shipped scenes and, since few of them are triangles alone, generated meshes of every
// kind (bench/mesh_generators.h) in a scene of their own.
std::vector<std::filesystem::path> scenes_to_walk(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> scenes = test::shipped_scenes();
  const std::pair<const char*, uint32_t> meshes[] = {{"sphere", 20000}, {"terrain", 20000}, {"cubes", 2000},
                                                     {"mixed", 20000},  {"boxes", 36},      {"icosphere", 1280}};
  for (const auto& [kind, triangles] : meshes) {
    const std::string name = std::string(kind) + "-" + std::to_string(triangles);
    write_obj(generate_mesh(kind, triangles), (dir / (name + ".obj")).string());
    std::ofstream(dir / (name + ".json")) << R"({ "format": "tracer-scene/1",
  "camera": { "from": [0, 0.5, 4], "to": [0, 0, 0], "vfov": 40 }, "film": { "width": 32, "height": 24 },
  "materials": { "clay": { "type": "lambert", "albedo": [0.8, 0.5, 0.3] } },
  "lights": [ { "type": "point", "position": [-2, 4, 3], "intensity": [25, 25, 25] } ],
  "shapes": [ { "type": "mesh", "file": ")" + name +
                                                 R"(.obj", "material": "clay" } ] })";
    scenes.push_back(dir / (name + ".json"));
  }
  return scenes;
}

TEST(BvhPairs, ThePairWalkGivesTheNodeWalksHitsInEveryShippedSceneAndGeneratedMesh) {
  ASSERT_GE(kBvhTriangles, 0);
  const std::filesystem::path dir = test::temp_dir("bvh-pairs");
  int walked = 0;
  for (const auto& scene_path : scenes_to_walk(dir))
    for (const AccelKind accel : {AccelKind::Bvh, AccelKind::Lbvh}) {
      RenderOverrides ov;
      ov.accel = accel;
      const Scene scene = load_scene(scene_path.string(), ov);
      const BvhPairs pairs = build_bvh_pairs(scene.bvh_nodes, scene.bounded, scene.primitives, scene_path.string());
      if (pairs.nodes.empty()) continue;
      ++walked;
      SceneView nodes = scene.view();
      nodes.wide_node_count = 0;
      const SceneView paired = with_pairs(nodes, pairs);
      const std::string what = scene_path.string() + (accel == AccelKind::Bvh ? " with bvh" : " with lbvh");
      const std::vector<Ray> rays = test::probe_rays(scene);
      expect_same_hits(what, nodes, paired, rays, false);
      if (trace_variant_of(scene.features, scene.settings, false, true) == kBvhTriangles)
        expect_same_hits(what + ", variant bvh_triangles", nodes, paired, rays, true);
    }
  std::filesystem::remove_all(dir);
  EXPECT_GE(walked, 12) << "the generated meshes, all triangles, were not all walked under both structures";
}

// A chain of interior nodes whose second child is always a leaf, every box the same: the walk
// visits the first child of a tie and pushes the leaf, so a chain longer than the stack sends
// it to the node walk. Interior node k sits at 0 (k = 0) or 2k - 1, its children at 2k + 1 (the
// next interior node, or the last leaf) and 2k + 2 (the leaf of triangle k).
struct Chain {
  SceneArrays arrays;
  SceneView view{};
};

Chain deep_chain(uint32_t levels) {
  Chain c;
  const Vec3 lo = {-1.0f, -1.0f, 0.0f}, hi = {1.0f, 1.0f, static_cast<float>(levels) + 1.0f};
  for (uint32_t i = 0; i <= levels; ++i) {  // triangle i at z = i + 1, across the rays
    const float z = static_cast<float>(i) + 1.0f;
    c.arrays.primitives.push_back(
        {ShapeKind::Triangle, 0, -1, 0.0f, {-1.0f, -1.0f, z}, {1.0f, -1.0f, z}, {0.0f, 1.0f, z}});
    c.arrays.bounded.push_back(i);
  }
  c.arrays.bvh_nodes.resize(2 * levels + 1);
  for (uint32_t k = 0; k < levels; ++k) {
    c.arrays.bvh_nodes[k == 0 ? 0 : 2 * k - 1] = {lo, 2 * k + 1, hi, 0};
    c.arrays.bvh_nodes[2 * k + 2] = {lo, k, hi, 1};
  }
  c.arrays.bvh_nodes[2 * levels - 1] = {lo, levels, hi, 1};
  point_view_at(c.view, c.arrays);
  c.view.settings.accel = AccelKind::Bvh;
  c.view.settings.triangle_test = TriangleTest::Watertight;
  return c;
}

TEST(BvhPairs, AChainAsDeepAsTheStackIsWalkedAndADeeperOneRefused) {
  for (const uint32_t levels : {8u, 63u, kBvhPairStackSize}) {
    Chain c = deep_chain(levels);
    const BvhPairs pairs = build_bvh_pairs(c.arrays.bvh_nodes, c.arrays.bounded, c.arrays.primitives, "chain");
    ASSERT_EQ(pairs.nodes.size(), levels);
    const SceneView paired = with_pairs(c.view, pairs);
    std::vector<Ray> rays;
    for (int i = 0; i < 16; ++i) {  // from below the first triangle, from between two, from above
      const float x = -0.3f + 0.04f * static_cast<float>(i);
      rays.push_back({{x, -0.2f, 0.5f}, {0.0f, 0.0f, 1.0f}});
      rays.push_back({{x, -0.2f, static_cast<float>(levels) - 0.5f}, {0.0f, 0.0f, 1.0f}});
      rays.push_back({{x, -0.2f, static_cast<float>(levels) + 1.5f}, {0.0f, 0.0f, -1.0f}});
    }
    expect_same_hits("a chain of " + std::to_string(levels), c.view, paired, rays, false);
    EXPECT_EQ(trace_closest(paired, rays[0], kInfinity).prim, 0u) << "the nearest triangle of the chain";
  }
  Chain deeper = deep_chain(kBvhPairStackSize + 1);
  try {
    build_bvh_pairs(deeper.arrays.bvh_nodes, deeper.arrays.bounded, deeper.arrays.primitives, "deep.bundle");
    ADD_FAILURE() << "a tree deeper than the stack was given records";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deep.bundle: bvh_nodes: node "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("deeper than a walk's stack"), std::string::npos) << e.what();
  }
}

TEST(BvhPairs, TheBuilderRefusesATreeThatPointsOutsideItsArrays) {
  Chain c = deep_chain(4);
  const auto refused = [&](const std::string& needle) {
    try {
      build_bvh_pairs(c.arrays.bvh_nodes, c.arrays.bounded, c.arrays.primitives, "edited.bundle");
    } catch (const InputError& e) {
      const std::string message = e.what();
      return message.find("edited.bundle: bvh_nodes: ") == 0 && message.find(needle) != std::string::npos;
    }
    return false;
  };
  const SceneArrays good = c.arrays;  // nodes 0, 1, 3, 5 interior; 2, 4, 6, 7, 8 leaves
  c.arrays.bvh_nodes[0].first = 7;    // the root's children are leaves 7 and 8: unusual, not wrong
  EXPECT_FALSE(refused(""));
  c.arrays = good;
  c.arrays.bvh_nodes[0].first = 8;
  EXPECT_TRUE(refused("children lie outside"));
  c.arrays = good;
  c.arrays.bvh_nodes[3].first = 0;  // a child is the root: a cycle
  EXPECT_TRUE(refused("reached twice"));
  c.arrays = good;
  c.arrays.bvh_nodes[8].first = 5;  // the leaf's one triangle is past the bounded array
  EXPECT_TRUE(refused("lie outside the 5 bounded"));
  c.arrays = good;
  c.arrays.bounded[1] = 99;
  EXPECT_TRUE(refused("is not one of the 5 primitives"));
}

TEST(BvhPairs, NoRecordsWhereTheRootIsALeafOrALeafHoldsAnotherShape) {
  Chain c = deep_chain(4);
  c.arrays.primitives[2].kind = ShapeKind::Sphere;
  EXPECT_TRUE(build_bvh_pairs(c.arrays.bvh_nodes, c.arrays.bounded, c.arrays.primitives, "s").nodes.empty());
  const std::vector<BvhNode> lone_leaf = {{{-1, -1, 0}, 0, {1, 1, 6}, 5}};
  EXPECT_TRUE(build_bvh_pairs(lone_leaf, c.arrays.bounded, c.arrays.primitives, "s").nodes.empty());
}

}  // namespace
}  // namespace tracer
