// The glTF reader (docs/gltf.md): accessors of every component type, sparse and strided;
// node transforms; cameras and lights; materials and textures; and every hostile file
// refused with an InputError naming the file and the JSON path inside it.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_builder.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class GltfReader : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("gltf"); }
  void TearDown() override { fs::remove_all(dir_); }

  Scene load(const json& doc, RenderOverrides ov = {}) {
    if (!ov.width) ov.width = 16;
    return load_scene(test::write_gltf(dir_ / "t.gltf", doc), ov);
  }
  void expect_error(const json& doc, const std::string& expected, RenderOverrides ov = {}) {
    try {
      load(doc, ov);
      ADD_FAILURE() << "accepted " << doc.dump().substr(0, 400);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("t.gltf"), std::string::npos) << e.what();
    }
  }
  // The buffer's bytes replaced (and its byteLength with them).
  static void set_buffer(json& doc, const std::string& bytes) {
    doc["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", test::data_uri(bytes)}};
  }

  fs::path dir_;
};

TEST_F(GltfReader, ATriangleWithItsCameraAndFilm) {
  const Scene s = load(test::triangle_gltf());
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].a, (Vec3{-1, -1, 0}));
  EXPECT_EQ(s.primitives[0].c, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.settings.width, 16u);
  EXPECT_EQ(s.settings.height, 8u);  // the camera's aspect ratio 2
  EXPECT_EQ(s.camera.origin, (Vec3{0, 0, 3}));
  EXPECT_EQ(s.materials[0].kind, MaterialKind::GltfMetalRough);
  EXPECT_EQ(s.materials[0].roughness, 0.5f);
  EXPECT_EQ(s.background.radiance, (Vec3{1, 1, 1}));  // no lights of its own: a white sky
}

TEST_F(GltfReader, EveryIndexTypeAndNoIndicesGiveTheSameTriangle) {
  for (const auto& [type, bytes] :
       {std::pair{5121, std::string("\0\1\2", 3)}, std::pair{5125, test::bytes_of(std::vector<uint32_t>{0, 1, 2})}}) {
    json doc = test::triangle_gltf();
    const std::vector<float> p = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    set_buffer(doc, test::bytes_of(p) + bytes);
    doc["bufferViews"][1]["byteLength"] = bytes.size();
    doc["accessors"][1]["componentType"] = type;
    EXPECT_EQ(load(doc).primitives[0].b, (Vec3{1, -1, 0})) << type;
  }
  json doc = test::triangle_gltf();
  doc["meshes"][0]["primitives"][0].erase("indices");
  EXPECT_EQ(load(doc).primitives[0].b, (Vec3{1, -1, 0}));
}

TEST_F(GltfReader, NormalizedIntegersStridesAndSparseSubstitution) {
  json doc = test::triangle_gltf();
  // Positions as normalized signed shorts, 8 bytes apart: (-1, -1, 0), (1, -1, 0), (0, 1, 0).
  const std::vector<int16_t> p = {-32767, -32767, 0, 0, 32767, -32767, 0, 0, 0, 32767, 0, 0};
  set_buffer(doc, test::bytes_of(p) + test::bytes_of(std::vector<uint16_t>{0, 1, 2}));
  doc["bufferViews"][0] = {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 24}, {"byteStride", 8}};
  doc["bufferViews"][1]["byteOffset"] = 24;
  doc["accessors"][0]["componentType"] = 5122;
  doc["accessors"][0]["normalized"] = true;
  EXPECT_EQ(load(doc).primitives[0].b, (Vec3{1, -1, 0}));
  // Sparse: vertex 2 replaced by (0, 0.5, 0).
  const std::string extra =
      test::bytes_of(std::vector<uint16_t>{2, 0}) + test::bytes_of(std::vector<int16_t>{0, 16384, 0});
  set_buffer(doc, test::bytes_of(p) + test::bytes_of(std::vector<uint16_t>{0, 1, 2}) + extra);
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 30}, {"byteLength", 2}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 34}, {"byteLength", 6}});
  doc["accessors"][0]["sparse"] = {
      {"count", 1}, {"indices", {{"bufferView", 2}, {"componentType", 5123}}}, {"values", {{"bufferView", 3}}}};
  EXPECT_NEAR(load(doc).primitives[0].c.y, 16384.0f / 32767.0f, 1e-7f);
}

TEST_F(GltfReader, MatrixAndTrsNodesAgreeThroughTheHierarchy) {
  json doc = test::triangle_gltf();
  doc["scenes"][0]["nodes"] = {2, 1};
  doc["nodes"][0]["translation"] = {0, 0, -2};
  doc["nodes"].push_back({{"children", {0}}, {"scale", {2, 2, 2}}});
  const Vec3 trs = load(doc).primitives[0].a;
  EXPECT_EQ(trs, (Vec3{-2, -2, -4}));  // scaled after the child's translation
  doc["nodes"][2] = {{"children", {0}}, {"matrix", {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}}};
  EXPECT_EQ(load(doc).primitives[0].a, trs);
}

TEST_F(GltfReader, CamerasByNameOrIndexAndAFramingCameraWithoutOne) {
  json doc = test::triangle_gltf();
  doc["cameras"].push_back(
      {{"type", "perspective"}, {"name", "far"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
  doc["nodes"].push_back({{"camera", 1}, {"translation", {0, 0, 9}}});
  doc["scenes"][0]["nodes"].push_back(2);
  RenderOverrides ov;
  ov.camera = "far";
  EXPECT_EQ(load(doc, ov).camera.origin, (Vec3{0, 0, 9}));
  ov.camera = "0";
  EXPECT_EQ(load(doc, ov).camera.origin, (Vec3{0, 0, 3}));
  ov.camera = "near";
  expect_error(doc, "--camera: no perspective camera \"near\" in the file (it places 0 \"cam\", 1 \"far\")", ov);
  doc.erase("cameras");
  doc["scenes"][0]["nodes"] = {0};
  const Scene framed = load(doc);
  EXPECT_EQ(framed.camera.origin.x, 0.0f);
  EXPECT_GT(framed.camera.origin.z, 1.0f);  // in front of the triangle, looking down -z
  EXPECT_EQ(framed.settings.height, 12u);   // 16 x 4:3 without a camera's aspect ratio
}

TEST_F(GltfReader, PunctualLightsInTheirUnitsShiningAlongTheNodesMinusZ) {
  json doc = test::triangle_gltf();
  json& light = doc["extensions"]["KHR_lights_punctual"]["lights"];
  light = {{{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 8}}};
  doc["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  Scene s = load(doc);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].kind, LightKind::Point);
  EXPECT_EQ(s.lights[0].intensity, (Vec3{8, 4, 2}));  // candela
  EXPECT_EQ(s.lights[0].position, (Vec3{0, 0, 3}));
  EXPECT_EQ(s.background.radiance, (Vec3{1, 1, 1}));  // lit by its own lights, and the viewer's sky

  // Turned 90 degrees about +x, the node's -z is +y.
  doc["nodes"][1]["rotation"] = {std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
  light[0]["type"] = "spot";
  light[0]["spot"] = {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}};
  s = load(doc);
  EXPECT_EQ(s.lights[0].kind, LightKind::Spot);
  EXPECT_EQ(s.lights[0].position, (Vec3{0, 0, 3}));
  EXPECT_NEAR(s.lights[0].direction.y, 1.0f, 1e-6f);
  EXPECT_NEAR(s.lights[0].direction.z, 0.0f, 1e-6f);
  EXPECT_EQ(s.lights[0].cos_inner, static_cast<float>(std::cos(0.25)));
  EXPECT_EQ(s.lights[0].cos_outer, static_cast<float>(std::cos(0.5)));
  light[0]["spot"]["innerConeAngle"] = 0.75;
  expect_error(doc, "extensions.KHR_lights_punctual.lights[0].spot: expected cone half-angles");

  light[0].erase("spot");
  light[0]["type"] = "directional";
  s = load(doc);
  EXPECT_EQ(s.lights[0].kind, LightKind::Directional);
  EXPECT_EQ(s.lights[0].intensity, (Vec3{8, 4, 2}));  // lux
  EXPECT_NEAR(s.lights[0].direction.y, 1.0f, 1e-6f);
  EXPECT_EQ(s.lights[0].one_minus_cos, 0.0f);  // parallel light: glTF's sun has no size
  light[0]["type"] = "area";
  expect_error(doc, "extensions.KHR_lights_punctual.lights[0].type: a light of type \"area\"");
}

TEST_F(GltfReader, MaterialsFactorsEmissionAndTheDiffuseSpecialCase) {
  json doc = test::triangle_gltf();
  doc["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 1.8;
  doc["materials"][0]["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 0.25;
  Material m = load(doc).materials[0];
  EXPECT_EQ(m.ior, 1.8f);
  EXPECT_EQ(m.transmission, 0.25f);
  doc["materials"][0]["extensions"].erase("KHR_materials_transmission");
  doc["materials"][0]["extensions"]["KHR_materials_specular"]["specularFactor"] = 0;
  EXPECT_EQ(load(doc).materials[0].kind, MaterialKind::Lambert);
  doc["materials"][0]["emissiveFactor"] = {1, 0.5, 0};
  doc["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 4;
  m = load(doc).materials[0];
  EXPECT_EQ(m.kind, MaterialKind::Lambert);  // emitting as well as reflecting
  EXPECT_EQ(m.radiance, (Vec3{4, 2, 0}));
  doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 1.5;
  expect_error(doc, "materials[0].pbrMetallicRoughness.roughnessFactor: must be in [0, 1]");
}

TEST_F(GltfReader, HostileAccessorsAndBuffers) {
  json doc = test::triangle_gltf();
  doc["accessors"][0]["count"] = 4;
  expect_error(doc, "accessors[0]: 4 elements of 12 bytes");
  doc = test::triangle_gltf();
  doc["accessors"][0]["count"] = 4294967296ull;
  expect_error(doc, "accessors[0].count");
  doc = test::triangle_gltf();
  doc["bufferViews"][0]["byteOffset"] = 40;
  expect_error(doc, "bufferViews[0].byteLength: bytes [40, +36) lie outside buffer 0 of 42 bytes");
  doc = test::triangle_gltf();
  doc["accessors"][0]["bufferView"] = 7;
  expect_error(doc, "names buffer view 7");
  doc = test::triangle_gltf();
  set_buffer(doc, test::bytes_of(std::vector<float>{-1, -1, 0, 1, -1, 0, 0, 1, 0}) +
                      test::bytes_of(std::vector<uint16_t>{0, 1, 9}));
  expect_error(doc, "meshes[0].primitives[0].indices: index 9 is beyond the 3 vertices of POSITION");
  doc = test::triangle_gltf();
  doc["bufferViews"][0]["byteStride"] = 4;
  expect_error(doc, "bufferViews[0].byteStride");
  // An image's view is read while tinygltf loads the file (before the checks above): the
  // sanitize build's fuzzer found it read past the buffer.
  doc = test::triangle_gltf();
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 8}, {"byteLength", 100}});
  doc["images"] = {{{"bufferView", 2}, {"mimeType", "image/png"}}};
  expect_error(doc, "images[0].bufferView: bytes [8, +100) lie outside buffer 0 of 42 bytes");
}

TEST_F(GltfReader, HostileHierarchiesAndFiles) {
  json doc = test::triangle_gltf();
  doc["nodes"][0]["children"] = {0};
  expect_error(doc, "nodes[0]: is reached twice");
  doc = test::triangle_gltf();
  doc["nodes"][0]["matrix"] = {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expect_error(doc, "nodes[0].matrix: is not affine");
  doc = test::triangle_gltf();
  doc["nodes"][0]["translation"] = {0, 1e300, 0};  // no float holds it
  expect_error(doc, "nodes[0]: 1000000");
  fs::create_directories(dir_ / "in");
  std::ofstream(dir_ / "outside.bin") << std::string(42, '\0');
  fs::create_symlink(dir_ / "outside.bin", dir_ / "in" / "link.bin");
  for (const std::string& uri :
       std::vector<std::string>{"../outside.bin", (dir_ / "outside.bin").string(), "link.bin"}) {
    doc = test::triangle_gltf();
    doc["buffers"][0]["uri"] = uri;
    try {
      load_scene(test::write_gltf(dir_ / "in" / "t.gltf", doc));
      ADD_FAILURE() << uri;
    } catch (const InputError& e) {
      const std::string why = uri[0] == '/' ? "buffers[0].uri: an absolute path" : "lies outside";
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
  doc = test::triangle_gltf();
  doc["images"] = {{{"uri", "data:image/png;base64," + test::base64("not a png at all")}}};
  doc["textures"] = {{{"source", 0}}};
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 0;
  doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 0;
  expect_error(doc, "textures[0]: images[0]: not a PNG or JPEG image");
  doc = test::triangle_gltf();
  doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 0;
  expect_error(doc, "accessors[0].type: has 3 components; meshes[0].primitives[0].attributes.TEXCOORD_0 needs 2");
}

TEST_F(GltfReader, MalformedJsonAndUnsupportedPartsAreNamed) {
  std::ofstream(dir_ / "bad.gltf") << R"({"asset": {"version": "2.0"}, "nodes": [)";
  EXPECT_THROW(load_scene((dir_ / "bad.gltf").string()), InputError);
  std::ofstream(dir_ / "deep.gltf") << std::string(100000, '[');
  EXPECT_THROW(load_scene((dir_ / "deep.gltf").string()), InputError);
  json doc = test::triangle_gltf();
  doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
  doc["meshes"][0]["primitives"][1]["mode"] = 1;
  const Scene s = load(doc);
  EXPECT_EQ(s.primitives.size(), 1u);
  ASSERT_GE(s.report.gltf.size(), 3u);
  EXPECT_NE(s.report.gltf[2].find("meshes[0].primitives[1]: mode 1"), std::string::npos) << s.report.gltf[2];
  doc["meshes"][0]["primitives"].erase(0);
  expect_error(doc, "places no triangles");
}

}  // namespace
}  // namespace tracer
