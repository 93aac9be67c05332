// Scene loading: transforms, boxes, OBJ fan triangulation, defaults and the feature mask.
#include <gtest/gtest.h>

#include <fstream>

#include "io/input_error.h"
#include "test_util.h"

using namespace tracer;

namespace {
std::string scene_with(const std::string& shapes, const std::string& extra = "") {
  return R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 0, 10], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 8},)" +
         extra + R"(
    "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]},
                  "g": {"type": "dielectric", "ior": 1.5}},
    "shapes": [)" +
         shapes + "]}";
}
void expect_near(Vec3 a, Vec3 b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
}  // namespace

TEST(SceneLoader, TransformsApplyInOrder) {
  // scale 2, then rotate +90 degrees about y (x -> -z), then translate.
  const Scene s = test::scene_from(scene_with(R"({"type": "sphere", "center": [1, 0, 0], "radius": 0.5, "material": "m",
      "transform": [{"scale": 2}, {"rotate": {"axis": [0, 1, 0], "degrees": 90}}, {"translate": [0, 1, 0]}]})"));
  ASSERT_EQ(s.primitives.size(), 1u);
  expect_near(s.primitives[0].a, {0, 1, -2});
  EXPECT_EQ(s.primitives[0].radius, 1.0f);
}

TEST(SceneLoader, RotateXyzAppliesXFirst) {
  const Scene s = test::scene_from(
      scene_with(R"({"type": "triangle", "vertices": [[0, 1, 0], [1, 1, 0], [0, 1, 1]], "material": "m",
      "transform": [{"rotate_xyz": [90, 0, 90]}]})"));
  // (0,1,0) -> rot x 90 -> (0,0,1) -> rot z 90 -> (0,0,1)
  expect_near(s.primitives[0].a, {0, 0, 1});
  // (1,1,0) -> rot x 90 -> (1,0,1) -> rot z 90 -> (0,1,1)
  expect_near(s.primitives[0].b, {0, 1, 1});
}

TEST(SceneLoader, NonUniformScaleOfSphereIsAnError) {
  EXPECT_THROW(test::scene_from(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m",
      "transform": [{"scale": [1, 2, 1]}]})")),
               InputError);
}

TEST(SceneLoader, BoxIsSixOutwardQuads) {
  const Scene s =
      test::scene_from(scene_with(R"({"type": "box", "min": [-1, -2, -3], "max": [1, 2, 3], "material": "m"})"));
  ASSERT_EQ(s.primitives.size(), 6u);
  Vec3 centre = {0, 0, 0};
  for (const Primitive& p : s.primitives) {
    ASSERT_EQ(p.kind, ShapeKind::Quad);
    const Vec3 face_centre = p.a + p.b * 0.5f + p.c * 0.5f;
    EXPECT_GT(dot(cross(p.b, p.c), face_centre - centre), 0.0f) << "inward-facing box face";
  }
  EXPECT_EQ(s.report.shape_counts.at("box"), 1u);
}

TEST(SceneLoader, ObjPolygonsAreFanTriangulatedWithNormalsAndUvs) {
  const auto dir = test::temp_dir("obj");
  std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\n"
                                     "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 1\n"
                                     "f 1/1/1 2/2/1 3/3/1 5/5/1 4/4/1\n";
  const std::string scene_path = (dir / "s.json").string();
  std::ofstream(scene_path) << scene_with(R"({"type": "mesh", "file": "quad.obj", "material": "m"})");
  const Scene s = load_scene(scene_path);
  ASSERT_EQ(s.primitives.size(), 3u);  // a pentagon: 3 fan triangles around vertex 1
  for (const Primitive& p : s.primitives) {
    EXPECT_EQ(p.a, (Vec3{0, 0, 0}));
    ASSERT_GE(p.shading, 0);
    EXPECT_EQ(s.triangle_shading[p.shading].has_normals, 1u);
    EXPECT_EQ(s.triangle_shading[p.shading].has_uvs, 1u);
  }
  EXPECT_EQ(s.primitives[1].b, (Vec3{1, 1, 0}));
  EXPECT_EQ(s.primitives[1].c, (Vec3{0.5f, 1.5f, 0}));
  EXPECT_TRUE(s.features & kFeatureShadingNormals);
  std::filesystem::remove_all(dir);
}

TEST(SceneLoader, FeatureMaskListsWhatTheSceneUses) {
  const Scene s =
      test::scene_from(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "g"},
      {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "m"})",
                                  R"("lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1]}],)"));
  EXPECT_EQ(s.features, kFeatureSphere | kFeaturePlane | kFeatureDielectric | kFeatureLambert | kFeatureDeclaredLights);
  EXPECT_EQ(feature_names(s.features),
            (std::vector<std::string>{"sphere", "plane", "lambert", "dielectric", "declared-lights"}));
  EXPECT_EQ(s.unbounded.size(), 1u);
  EXPECT_EQ(s.bounded.size(), 1u);
}

TEST(SceneLoader, EveryFeatureBitHasOneName) {
  for (uint32_t bit = 1; bit <= kFeatureMirrorImages; bit <<= 1) EXPECT_EQ(feature_names(bit).size(), 1u) << bit;
  EXPECT_EQ(feature_names(kFeatureMicrofacet), std::vector<std::string>{"microfacet"});
}

TEST(SceneLoader, DefaultsAndOverrides) {
  RenderOverrides ov;
  ov.spp = 9;
  ov.sampler = SamplerKind::Stratified;
  ov.width = 20;
  const Scene s =
      test::scene_from(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})"), ov);
  EXPECT_EQ(s.settings.spp, 9u);
  EXPECT_EQ(s.settings.grid_n, 3u);
  EXPECT_EQ(s.settings.width, 20u);
  EXPECT_EQ(s.settings.height, 8u);
  EXPECT_EQ(s.settings.integrator, IntegratorKind::Whitted);
  EXPECT_EQ(s.settings.accel, AccelKind::Bvh);
  EXPECT_EQ(s.settings.max_depth, 5u);
  const Scene plain =
      test::scene_from(scene_with(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})"));
  EXPECT_EQ(plain.settings.sampler, SamplerKind::Sobol);  // the default for a scene that names none
}

// Every shipped scene names its sampler, so the default (sobol since 2026-11-24, aec3dcd) moves no golden.
TEST(SceneLoader, EveryShippedSceneNamesItsSampler) {
  for (const auto& path : test::shipped_scenes())
    EXPECT_NE(test::read_file(path).find("\"sampler\""), std::string::npos) << path;
}

TEST(SceneLoader, EveryShippedSceneLoads) {
  for (const auto& path : test::shipped_scenes()) EXPECT_NO_THROW(load_scene(path.string())) << path;
}

// scenes/large/ uses meshes written by ci/generate-meshes.sh: they load when those meshes
// exist; otherwise the test says so and is skipped.
TEST(SceneLoader, LargeScenesLoadWhenTheirMeshesExist) {
  std::string missing;
  int loaded = 0;
  for (const auto& e : std::filesystem::directory_iterator(test::source_path("scenes/large"))) {
    if (e.path().extension() != ".json") continue;
    try {
      load_scene(e.path().string());
      ++loaded;
    } catch (const InputError& error) {
      const std::string what = error.what();
      if (what.find("generated/") == std::string::npos || what.find("no such file") == std::string::npos) throw;
      missing += "\n  " + what;
    }
  }
  if (!missing.empty()) GTEST_SKIP() << "meshes not generated (run bash ci/generate-meshes.sh):" << missing;
  EXPECT_GE(loaded, 1);
}
