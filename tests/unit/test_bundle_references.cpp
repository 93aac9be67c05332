// A scene bundle's indices and sizes checked against the arrays they point into
// (tracer/bundle/bundle_references.h): every bundle the tracer writes passes, under every
// structure; one edited field of each kind is refused, naming the array and the index. A
// checksum vouches for the bytes, not for a field edited before it was computed: tracer-gpu
// crashed (SIGSEGV, SIGFPE) or drew another image on such bundles.
#include <gtest/gtest.h>

#include <functional>

#include "bundle/bundle_references.h"
#include "scene/scene_loader.h"
#include "test_util.h"

namespace tracer {
namespace {

Scene feature_scene(const std::string& name, AccelKind accel) {
  RenderOverrides o;
  o.accel = accel;
  return load_scene(test::source_path("scenes/features/" + name), o);
}

std::string violation(const Scene& s) { return bundle_reference_violation(s, s.view()); }

constexpr AccelKind kEveryStructure[] = {AccelKind::None,   AccelKind::Bvh,          AccelKind::Lbvh,
                                         AccelKind::Kdtree, AccelKind::KdtreeMedian, AccelKind::Grid};

TEST(BundleReferences, EveryBundleTheTracerWritesPasses) {
  for (const char* name : {"mesh.json", "textures.json", "cubemap.json", "environment.json", "shadows.json",
                           "spot-room.json", "alpha.json", "maps.json", "sun-sky.json"})
    for (const AccelKind accel : kEveryStructure) {
      const Scene s = feature_scene(name, accel);
      EXPECT_EQ(violation(s), "") << name << " " << static_cast<int>(accel);
    }
}

Texture& first_image(Scene& s) {
  for (Texture& t : s.textures)
    if (t.kind == TextureKind::Image) return t;
  ADD_FAILURE() << "no image texture";
  return s.textures.at(0);
}

BvhNode& interior_below_the_root(Scene& s) {
  for (size_t i = 1; i < s.bvh_nodes.size(); ++i)
    if (s.bvh_nodes[i].count == 0) return s.bvh_nodes[i];
  ADD_FAILURE() << "no interior node below the root";
  return s.bvh_nodes.at(0);
}

struct Edit {
  const char* scene;
  AccelKind accel;
  std::function<void(Scene&)> edit;
  std::string expected;
};

TEST(BundleReferences, EachEditedIndexIsRefusedByName) {
  const Edit edits[] = {
      {"mesh.json", AccelKind::Bvh,
       [](Scene& s) { s.primitives[0].material = static_cast<uint32_t>(s.materials.size()); },
       "primitives[0]: material"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.primitives[0].kind = static_cast<ShapeKind>(7); },
       "primitives[0]: kind 7"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.primitives.back().shading = 1 << 30; }, "shading 1073741824 of"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.bounded[0] = static_cast<uint32_t>(s.primitives.size()); },
       "bounded[0]: primitive"},
      // planes are unbounded: a structure's leaves test without them
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.primitives[s.bounded[0]].kind = ShapeKind::Plane; },
       "bounded[0]: primitive"},
      {"mesh.json", AccelKind::Grid, [](Scene& s) { s.primitives[s.grid_prims[0]].kind = ShapeKind::Plane; },
       "is a plane, which no structure holds"},
      {"mesh.json", AccelKind::Lbvh,
       [](Scene& s) { s.bvh_nodes[0].first = static_cast<uint32_t>(s.bvh_nodes.size() - 1); },
       "bvh_nodes[0]: children"},
      {"mesh.json", AccelKind::Lbvh, [](Scene& s) { interior_below_the_root(s).first = 0; },
       "reached twice from the root"},
      {"mesh.json", AccelKind::Lbvh,
       [](Scene& s) {
         for (BvhNode& n : s.bvh_nodes)
           if (n.count > 0) n.count = 4000000000u;
       },
       "leaf primitives"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.wide_nodes[0].leaf_blocks[0] = 4000000000u; },
       "wide_nodes[0]: leaf blocks"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.triangle_blocks[0].id[0] = 4000000000u; },
       "triangle_blocks[0]: primitive"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.triangle_blocks[0].other_lanes = 0x10u; }, "lanes out of range"},
      {"mesh.json", AccelKind::Kdtree, [](Scene& s) { s.kd_nodes[0].axis = 5; }, "kd_nodes[0]: axis 5"},
      {"mesh.json", AccelKind::Kdtree, [](Scene& s) { s.kd_nodes[0].a = 0; }, "reached twice from the root"},
      {"mesh.json", AccelKind::Kdtree, [](Scene& s) { s.kd_prims[0] = 4000000000u; }, "kd_prims[0]: primitive"},
      {"mesh.json", AccelKind::Grid, [](Scene& s) { s.grid_cell_start[1] = 4000000000u; }, "grid_cell_start[1]"},
      {"mesh.json", AccelKind::Grid, [](Scene& s) { s.grid_prims[0] = 4000000000u; }, "grid_prims[0]: primitive"},
      {"mesh.json", AccelKind::Bvh, [](Scene& s) { s.materials[0].kind = static_cast<MaterialKind>(99); },
       "materials[0]: kind 99"},
      {"textures.json", AccelKind::Bvh, [](Scene& s) { s.materials[0].texture[0] = 12345; },
       "materials[0]: texture 12345 of"},
      {"textures.json", AccelKind::Bvh, [](Scene& s) { s.materials[0].normal_map = 12345; },
       "materials[0]: map 12345 of"},
      {"textures.json", AccelKind::Bvh, [](Scene& s) { first_image(s).width = 1u << 20; }, "]: 1048576 x"},
      {"textures.json", AccelKind::Bvh, [](Scene& s) { first_image(s).offset = 4000000000u; },
       "at 4000000000 lie outside"},
      {"shadows.json", AccelKind::Bvh, [](Scene& s) { s.light_table[0].index = 9999; }, "light_table[0]:"},
      {"shadows.json", AccelKind::Bvh, [](Scene& s) { s.light_table[0].kind = static_cast<LightKind>(9); },
       "light_table[0]: kind 9"},
      {"shadows.json", AccelKind::Bvh, [](Scene& s) { s.light_of_prim.pop_back(); }, "light_of_prim:"},
      {"shadows.json", AccelKind::Bvh, [](Scene& s) { s.light_of_prim[0] = 9999; }, "light_of_prim[0]: entry 9999 of"},
  };
  for (const Edit& e : edits) {
    Scene s = feature_scene(e.scene, e.accel);
    ASSERT_EQ(violation(s), "") << e.scene;
    e.edit(s);
    EXPECT_NE(violation(s).find(e.expected), std::string::npos) << e.expected << "\ngot: " << violation(s);
  }
  // The environment's entry and cells, the cube map's faces.
  Scene env = feature_scene("environment.json", AccelKind::Bvh);
  env.sky_cells.clear();
  EXPECT_NE(violation(env).find("the environment, but the bundle has no sky cells"), std::string::npos)
      << violation(env);
  Scene cube = feature_scene("cubemap.json", AccelKind::Bvh);
  cube.background.faces[3] = 777;
  EXPECT_NE(violation(cube).find("background: cube face 777"), std::string::npos) << violation(cube);
}

// A tree deeper than a walk's stack: the binary walks hold 64 entries, so an interior node may
// lie below at most 63 others. A chain of interior nodes, each with a leaf beside it.
TEST(BundleReferences, ATreeDeeperThanTheWalksStackIsRefused) {
  for (const uint32_t interior : {64u, 65u}) {
    Scene s = feature_scene("textures.json", AccelKind::Lbvh);
    s.wide_nodes.clear();
    s.bvh_nodes.assign(2 * interior + 1, BvhNode{{-1, -1, -1}, 0, {1, 1, 1}, 1});  // leaves of one primitive
    for (uint32_t i = 0; i < interior; ++i) s.bvh_nodes[2 * i] = BvhNode{{-1, -1, -1}, 2 * i + 1, {1, 1, 1}, 0};
    const std::string v = violation(s);
    if (interior == 64u)
      EXPECT_EQ(v, "") << "63 interior nodes above the deepest: its stack holds them";
    else
      EXPECT_NE(v.find("deeper than a walk's stack (63)"), std::string::npos) << v;
  }
}

}  // namespace
}  // namespace tracer
