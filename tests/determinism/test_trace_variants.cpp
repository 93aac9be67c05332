// The GPU stream schedule's trace variants (kernel/accel/trace_variants.h): each is the trace
// code compiled with only one structure's traversal and one set of shapes, and runs only the
// scenes whose needs it holds. Here, on the CPU, the same template code: each variant answers
// every probe ray of every shipped scene it runs, under every structure it holds (bvh's binary
// tree with pair records where the device builds them, and its 8-wide tree as the device holds
// it when asked), exactly as the full code does; and a scene runs on the variant the table says.
#include <gtest/gtest.h>

#include <cstring>

#include "accel/bvh_pairs_builder.h"
#include "accel/wide_bvh_builder.h"
#include "kernel/accel/trace.h"
#include "kernel/accel/trace_variants.h"
#include "options/enum_names.h"
#include "probe_rays.h"
#include "render/device_bvh.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"
#include "test_util.h"

namespace tracer {
namespace {

// Each variant's two queries, instantiated with its code.
struct VariantQueries {
  Hit (*closest)(const SceneView&, const Ray&, float);
  bool (*any)(const SceneView&, const Ray&, float);
};
#define TRACER_VARIANT_QUERIES(name, code) {trace_closest<code>, trace_any<code>},
constexpr VariantQueries kQueries[] = {TRACER_TRACE_VARIANTS(TRACER_VARIANT_QUERIES)};
#undef TRACER_VARIANT_QUERIES

void expect_variant_answers_as_full_code(const std::string& what, const SceneView& view, int v,
                                         const std::vector<Ray>& rays) {
  for (const Ray& ray : rays) {
    const Hit full = trace_closest(view, ray, kInfinity), h = kQueries[v].closest(view, ray, kInfinity);
    ASSERT_EQ(std::memcmp(&h, &full, sizeof(Hit)), 0)
        << what << ", variant " << kTraceVariants[v].name << ": prim " << h.prim << " t " << h.t << " against prim "
        << full.prim << " t " << full.t;
    const float tmax = full.prim != kNoHit ? full.t * 1.5f : 1e3f;
    ASSERT_EQ(kQueries[v].any(view, ray, tmax), trace_any(view, ray, tmax)) << what << ", " << kTraceVariants[v].name;
    // The any-hit query at exactly the closest hit's t: a hit at tmax does not occlude.
    if (full.prim != kNoHit) {
      ASSERT_EQ(kQueries[v].any(view, ray, full.t), trace_any(view, ray, full.t));
    }
  }
}

TEST(TraceVariants, EachVariantAnswersAsTheFullCodeInEveryShippedSceneItRuns) {
  int scenes_run[kTraceVariantCount] = {};
  for (const auto& scene_path : test::shipped_scenes())
    for (const std::string& accel : accepted_scene_types().at("accel")) {
      RenderOverrides ov;
      ov.accel = parse_enum<AccelKind>(accel, "accel");
      const Scene scene = load_scene(scene_path.string(), ov);
      for (const bool wide_tree : {false, true}) {
        if (wide_tree && scene.wide_nodes.empty()) continue;
        SceneView view = scene.view();  // the full code walks the wide tree where the view holds one
        BvhPairs pairs;                 // the binary tree's pair records where a device upload builds them
        if (!wide_tree) {
          view.wide_node_count = 0;
          if (device_pair_records(view)) {
            pairs = build_bvh_pairs(scene.bvh_nodes, scene.bounded, scene.primitives, scene_path.string());
            view.bvh_pairs = pairs.nodes.data();
            view.bvh_pair_triangles = pairs.triangles.data();
            view.bvh_pair_count = static_cast<uint32_t>(pairs.nodes.size());
          }
        }
        const int v = trace_variant_of(scene.features, scene.settings, wide_tree, view.bvh_pair_count != 0);
        if (v < 0) continue;
        ++scenes_run[v];
        expect_variant_answers_as_full_code(scene_path.string() + " with " + accel, view, v, test::probe_rays(scene));
      }
    }
  for (int v = 0; v < kTraceVariantCount; ++v)
    EXPECT_GT(scenes_run[v], 0) << kTraceVariants[v].name << " runs no shipped scene: nothing checks it";
}

TEST(TraceVariants, ASceneRunsOnTheFirstVariantThatHoldsItsNeeds) {
  const auto name = [](uint32_t features, AccelKind accel, TriangleTest test = TriangleTest::Watertight) {
    return std::string(trace_variant_name(trace_variant_for(trace_code_needed(features, accel, test))));
  };
  const auto name_with_wide_tree = [](uint32_t features, AccelKind accel) {
    return std::string(
        trace_variant_name(trace_variant_for(trace_code_needed(features, accel, TriangleTest::Watertight, true))));
  };
  const auto name_with_pairs = [](uint32_t features, AccelKind accel) {
    return std::string(trace_variant_name(
        trace_variant_for(trace_code_needed(features, accel, TriangleTest::Watertight, false, true))));
  };
  const uint32_t lambert = kFeatureLambert | kFeatureEmissive | kFeatureTextures;  // not shapes: no trace code
  EXPECT_EQ(name_with_pairs(kFeatureTriangle | lambert, AccelKind::Bvh), "bvh_triangles");
  EXPECT_EQ(name_with_pairs(kFeatureTriangle | kFeaturePlane, AccelKind::Lbvh), "bvh_triangles");
  // the binary tree without pair records (its root a leaf, or an upload of its nodes alone): the
  // first row that holds the node walk, the wide tree's, whose fallback it is
  EXPECT_EQ(name(kFeatureTriangle | lambert, AccelKind::Bvh), "wide_bvh_triangles");
  EXPECT_EQ(name(kFeatureTriangle | kFeaturePlane, AccelKind::Lbvh), "wide_bvh_triangles");
  EXPECT_EQ(name(kFeatureSphere | kFeaturePlane, AccelKind::Bvh), "bvh_spheres");
  EXPECT_EQ(name_with_wide_tree(kFeatureTriangle | kFeaturePlane, AccelKind::Bvh), "wide_bvh_triangles");
  // the wide tree is bvh's alone; a sphere scene's wide tree runs on the full code (on the GPU, its binary walk)
  EXPECT_EQ(name_with_wide_tree(kFeatureTriangle, AccelKind::Lbvh), "wide_bvh_triangles");
  EXPECT_EQ(name_with_wide_tree(kFeatureSphere, AccelKind::Bvh), "full");
  EXPECT_EQ(name(kFeatureTriangle, AccelKind::KdtreeMedian), "kdtree_triangles");
  EXPECT_EQ(name(kFeatureSphere, AccelKind::Kdtree), "kdtree_spheres");
  EXPECT_EQ(name(kFeatureTriangle, AccelKind::Grid), "grid_triangles");
  EXPECT_EQ(name(kFeatureSphere | lambert, AccelKind::Grid), "grid_spheres");
  // a plane alone needs no structure's shapes: the first row of its structure holds it
  EXPECT_EQ(name(kFeaturePlane, AccelKind::Grid), "grid_triangles");
  // what no row holds runs on the full code
  EXPECT_EQ(name(kFeatureTriangle, AccelKind::Bvh, TriangleTest::MollerTrumbore), "full");
  EXPECT_EQ(name(kFeatureTriangle | kFeatureSphere, AccelKind::Bvh), "full");
  EXPECT_EQ(name(kFeatureQuad, AccelKind::Bvh), "full");
  EXPECT_EQ(name(kFeatureSphere, AccelKind::None), "full");
  // a sphere scene's triangle test setting is no need of it
  EXPECT_EQ(name(kFeatureSphere, AccelKind::Bvh, TriangleTest::MollerTrumbore), "bvh_spheres");
}

// A tree deeper than the variant's stack is walked again by the binary traversal from the hit
// so far (the wide walk returns false, and trace_into goes on to the binary one): with a stack
// of 8 entries, every ray's answer in every shipped scene whose tree needs more is the full code's.
TEST(TraceVariants, AWideTreeDeeperThanTheStackGivesTheSameHits) {
  constexpr int kWide =
      trace_variant_for(trace_code_needed(kFeatureTriangle, AccelKind::Bvh, TriangleTest::Watertight, true));
  constexpr uint32_t kCode = kTraceVariants[kWide].code;
  int deeper = 0, walked_again = 0;
  for (const auto& scene_path : test::shipped_scenes()) {
    const Scene scene = load_scene(scene_path.string(), RenderOverrides{});
    if (trace_variant_of(scene.features, scene.settings, true, false) != kWide ||
        wide_bvh_stack_need(scene.wide_nodes) <= 8)
      continue;
    ++deeper;
    const SceneView view = scene.view();
    for (const Ray& ray : test::probe_rays(scene))
      for (const bool any : {false, true}) {
        Hit full = {any ? 10.0f : kInfinity, kNoHit, 0.0f, 0.0f}, shallow = full;
        const RayShear shear = make_ray_shear(ray.dir);
        ASSERT_TRUE(traverse_wide_bvh(view, ray, shear, full, any));  // the CPU's stack holds any tree
        if (!traverse_wide_bvh<kCode, 8>(view, ray, shear, shallow, any)) {
          ++walked_again;
          traverse_bvh<kCode>(view, ray, shear, shallow, any);
        }
        ASSERT_EQ(std::memcmp(&full, &shallow, sizeof(Hit)), 0)
            << scene_path << ", any " << any << ": prim " << shallow.prim;
      }
  }
  EXPECT_GT(deeper, 0) << "no shipped scene's tree is deeper than 8 entries: nothing checks the fallback";
  EXPECT_GT(walked_again, 0) << "no probe ray outgrew the stack of 8";
}

}  // namespace
}  // namespace tracer
