// OBJ meshes without a "material" take their MTL materials, mapped as documented in
// tracer/scene/mtl_materials.h: emissive, dielectric, metal, phong, lambert, maps included.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "image/image_io.h"
#include "io/input_error.h"
#include "test_util.h"

namespace tracer {
namespace {

const char* kObj = R"(mtllib things.mtl
v 0 0 0
v 1 0 0
v 0 1 0
vt 0 0
vt 1 0
vt 0 1
f 1/1 2/2 3/3
usemtl lamp
f 1 2 3
usemtl glass
f 1 2 3
usemtl chrome
f 1 2 3
usemtl plastic
f 1 2 3
usemtl clay
f 1/1 2/2 3/3
)";

const char* kMtl = R"(newmtl lamp
Kd 0.2 0.2 0.2
Ke 5 4 3
newmtl glass
Kd 0.9 1 0.9
Ni 1.45
d 0.3
newmtl chrome
illum 3
Kd 0 0 0
Ks 0.9 0.8 0.7
Ns 98
newmtl plastic
Kd 0.1 0.2 0.6
Ks 0.4 0.4 0.4
Ns 50
map_Ks spec.exr
newmtl clay
Kd 0.7 0.5 0.3
map_Kd clay.exr
bump clay.exr
)";

std::string mesh_scene(const std::string& obj) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 8}, "materials": {},
    "shapes": [{"type": "mesh", "file": ")" +
         obj + R"("}]})";
}

TEST(Mtl, EveryMappingRowAndFacesWithoutUsemtl) {
  const auto dir = test::temp_dir("mtl");
  std::ofstream(dir / "things.obj") << kObj;
  std::ofstream(dir / "things.mtl") << kMtl;
  write_image(Image{2, 2, std::vector<float>(12, 0.25f)}, (dir / "clay.exr").string());
  write_image(Image{2, 2, std::vector<float>(12, 1.0f)}, (dir / "spec.exr").string());
  const Scene scene = load_scene_text(mesh_scene("things.obj"), (dir / "s.json").string());
  ASSERT_EQ(scene.primitives.size(), 6u);
  const auto material_of = [&](int face) { return scene.materials[scene.primitives[face].material]; };
  EXPECT_EQ(material_of(0).kind, MaterialKind::Lambert) << "before any usemtl: grey lambert";
  EXPECT_EQ(material_of(0).albedo.x, 0.5f);
  const Material lamp = material_of(1);
  EXPECT_EQ(lamp.kind, MaterialKind::Emissive);
  EXPECT_EQ(lamp.radiance.x, 5.0f);
  EXPECT_EQ(lamp.albedo.x, 0.2f);
  const Material glass = material_of(2);
  EXPECT_EQ(glass.kind, MaterialKind::Dielectric);
  EXPECT_EQ(glass.ior, 1.45f);
  EXPECT_EQ(glass.tint.y, 1.0f);
  const Material chrome = material_of(3);
  EXPECT_EQ(chrome.kind, MaterialKind::PhongMetal);
  EXPECT_EQ(chrome.albedo.x, 0.9f);
  EXPECT_NEAR(chrome.roughness, std::sqrt(2.0f / 100.0f), 1e-6f);
  const Material plastic = material_of(4);
  EXPECT_EQ(plastic.kind, MaterialKind::Phong);
  EXPECT_EQ(plastic.shininess, 50.0f);
  EXPECT_NE(plastic.factor_map, kNoTexture);
  const Material clay = material_of(5);
  EXPECT_EQ(clay.kind, MaterialKind::Lambert);
  EXPECT_NE(clay.texture[kSlotAlbedo], kNoTexture);
  EXPECT_NE(clay.bump_map, kNoTexture);
  EXPECT_EQ(clay.albedo.x, 0.25f) << "a float map is linear; the colour holds its mean";
  for (const char* t :
       {"material:emissive", "material:dielectric", "material:metal", "material:phong", "material:lambert"})
    EXPECT_TRUE(scene.report.used_types.count(t)) << t;
  std::filesystem::remove_all(dir);
}

TEST(Mtl, MissingMtlOrMapIsAnError) {
  const auto dir = test::temp_dir("mtl-bad");
  std::ofstream(dir / "lost.obj") << "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";
  std::ofstream(dir / "things.obj") << kObj;
  std::ofstream(dir / "things.mtl") << kMtl;  // clay.exr and spec.exr are missing
  const struct {
    std::string obj, expected;
  } cases[] = {{"lost.obj", "shapes[0].file: "},
               {"lost.obj", "names no MTL materials"},
               {"things.obj", "shapes[0].file (MTL material \"plastic\")"}};
  for (const auto& c : cases) test::expect_load_error(dir, mesh_scene(c.obj), c.expected);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
