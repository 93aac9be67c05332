// glTF files the specification allows load (docs/gltf.md, "What is read"): each is the
// triangle of gltf_builder.h plus one construct a hand-written or optimised file may hold,
// and the Khronos validator (npm gltf-validator, fetched by ci/fetch-gltf-validator.sh) finds
// no error in any of them. Refusals name the file and the JSON path in the reader's words.
#include <gtest/gtest.h>

#include <cctype>
#include <functional>

#include "gltf_builder.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kTriangleBytes =
    test::bytes_of(std::vector<float>{-1, -1, 0, 1, -1, 0, 0, 1, 0}) + test::bytes_of(std::vector<uint16_t>{0, 1, 2});

std::string percent_encoded(const std::string& bytes) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : bytes)
    out += std::isalnum(c) ? std::string(1, char(c)) : std::string{'%', hex[c >> 4], hex[c & 15]};
  return out;
}

// The triangle's buffer with three normals (0, 0, 1) after it, accessor 2 reading them.
json with_normals(json doc) {
  const std::string bytes =
      kTriangleBytes + std::string(2, '\0') + test::bytes_of(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
  doc["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", test::data_uri(bytes)}};
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 36}});
  doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  return doc;
}

struct ValidFile {
  std::string name;  // the file written, and what it shows
  std::function<std::string(const fs::path& dir)> write;
};

std::vector<ValidFile> valid_files() {
  const auto gltf = [](const std::string& name, std::function<void(json&)> edit) {
    return ValidFile{name, [=](const fs::path& dir) {
                       json doc = test::triangle_gltf();
                       edit(doc);
                       return test::write_gltf(dir / name, doc);
                     }};
  };
  return {
      gltf("integers-written-as-floats.gltf",
           [](json& d) {
             d["bufferViews"][1]["byteLength"] = 6.0;
             d["accessors"][0]["count"] = 3.0;
             d["scene"] = 0.0;
           }),
      gltf("unused-buffer-without-uri.gltf",
           [](json& d) {
             d["buffers"].push_back({{"byteLength", 12}});
           }),
      gltf(
          "percent-encoded-data-uri.gltf",
          [](json& d) { d["buffers"][0]["uri"] = "data:application/octet-stream," + percent_encoded(kTriangleBytes); }),
      gltf("unused-accessor-of-unknown-type.gltf",
           [](json& d) {
             d["accessors"].push_back({{"componentType", 5126}, {"count", 1}, {"type", "MAT5"}});
           }),
      gltf("index-accessor-without-buffer-view.gltf",
           [](json& d) {  // zeros: one triangle without area, left out
             d["accessors"].push_back({{"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
             d["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"indices", 2}});
           }),
      gltf("primitive-without-position.gltf",
           [](json& d) {
             d = with_normals(d);
             d["meshes"][0]["primitives"].push_back({{"attributes", {{"NORMAL", 2}}}});
           }),
      {"second-buffer-without-uri.glb",
       [](const fs::path& dir) {
         json doc = test::triangle_gltf();
         doc["buffers"] = {{{"byteLength", kTriangleBytes.size()}}, {{"byteLength", 8}}};
         return test::write_glb(dir / "second-buffer-without-uri.glb", doc, kTriangleBytes);
       }},
      gltf("quantized-mesh.gltf",
           [](json& d) {  // KHR_mesh_quantization: short positions under a scale, byte normals
             const std::string bytes =
                 test::bytes_of(std::vector<int16_t>{-100, -100, 0, 0, 100, -100, 0, 0, 0, 100, 0, 0}) +
                 test::bytes_of(std::vector<uint16_t>{0, 1, 2, 0}) +
                 test::bytes_of(std::vector<int8_t>{0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0});
             d["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", test::data_uri(bytes)}};
             d["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 24}, {"byteStride", 8}},
                                 {{"buffer", 0}, {"byteOffset", 24}, {"byteLength", 6}},
                                 {{"buffer", 0}, {"byteOffset", 32}, {"byteLength", 12}, {"byteStride", 4}}};
             d["accessors"][0] = {{"bufferView", 0}, {"componentType", 5122},  {"count", 3},
                                  {"type", "VEC3"},  {"min", {-100, -100, 0}}, {"max", {100, 100, 0}}};
             d["accessors"].push_back(
                 {{"bufferView", 2}, {"componentType", 5120}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}});
             d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
             d["nodes"][0]["scale"] = {0.01, 0.01, 0.01};
             d["extensionsUsed"] = {"KHR_mesh_quantization"};
             d["extensionsRequired"] = {"KHR_mesh_quantization"};
           }),
  };
}

TEST(GltfValidFiles, EveryConstructTheSpecificationAllowsLoads) {
  const auto dir = test::temp_dir("gltf-valid");
  for (const ValidFile& f : valid_files()) {
    try {
      const Scene s = load_scene(f.write(dir));
      ASSERT_EQ(s.primitives.size(), 1u) << f.name;
      EXPECT_NEAR(s.primitives[0].b.x, 1.0f, 1e-6f) << f.name;  // the triangle's second corner
      EXPECT_NEAR(s.primitives[0].c.y, 1.0f, 1e-6f) << f.name;
    } catch (const InputError& e) {
      ADD_FAILURE() << f.name << ": " << e.what();
    }
  }
  fs::remove_all(dir);
}

TEST(GltfValidFiles, TheKhronosValidatorFindsNoErrorInThem) {
  const std::string package = test::source_path("scenes/generated/gltf-validator");
  if (test::run_command("command -v node") != 0)
    GTEST_SKIP() << "node is not installed (ci/install-deps.sh installs it)";
  if (!fs::exists(package + "/index.js"))
    GTEST_SKIP() << package << " is absent: bash ci/fetch-gltf-validator.sh fetches it from the npm registry";
  const auto dir = test::temp_dir("gltf-validator");
  std::string files;
  for (const ValidFile& f : valid_files()) files.append(" ").append(f.write(dir));
  std::string out;
  ASSERT_EQ(
      test::run_command("node " + test::source_path("tests/support/gltf_validate.js") + " " + package + files, &out), 0)
      << out;
  for (const ValidFile& f : valid_files()) EXPECT_NE(out.find(f.name + ": 0 errors"), std::string::npos) << out;
  fs::remove_all(dir);
}

void expect_refused(const fs::path& file, const std::string& expected) {
  try {
    load_scene(file.string());
    ADD_FAILURE() << "accepted " << file;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.filename().string() + ": " + expected), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("tinygltf"), std::string::npos) << e.what();
  }
}

TEST(GltfValidFiles, RefusalsNameTheJsonPathInTheReadersWords) {
  const auto dir = test::temp_dir("gltf-refusals");
  json doc = test::triangle_gltf();
  doc["accessors"][0].erase("componentType");
  expect_refused(test::write_gltf(dir / "a.gltf", doc), "accessors[0].componentType: is missing");
  doc = test::triangle_gltf();
  doc["buffers"][0].erase("uri");
  expect_refused(test::write_gltf(dir / "b.gltf", doc), "buffers[0]: has no uri");
  doc["buffers"][0]["uri"] = "";  // the folder itself, once
  expect_refused(test::write_gltf(dir / "c.gltf", doc), "buffers[0]: has no uri");
  doc = test::triangle_gltf();
  doc["buffers"][0]["uri"] = "data:application/octet-stream,%4";
  expect_refused(test::write_gltf(dir / "d.gltf", doc), "buffers[0].uri: a data URI with a '%'");
  doc = test::triangle_gltf();
  doc["extensionsRequired"] = {"KHR_mesh_quantization", "EXT_meshopt_compression"};
  expect_refused(test::write_gltf(dir / "e.gltf", doc),
                 "extensionsRequired[1]: the file requires EXT_meshopt_compression");
  doc = test::triangle_gltf();
  doc["buffers"][0]["uri"] = "missing.bin";
  expect_refused(test::write_gltf(dir / "g.gltf", doc),
                 "buffers[0].uri: " + (dir / "missing.bin").string() + ": no such file");
  doc = test::triangle_gltf();
  doc["accessors"][0]["count"] = 2.5;
  expect_refused(test::write_gltf(dir / "f.gltf", doc), "accessors[0].count: expected a whole number >= 0, got 2.5");
  fs::remove_all(dir);
}

// Numbers a reader must not take at face value: references of 2^31 and above wrapped in
// tinygltf's int ("mesh": 4294967295 became no mesh, "POSITION": 4294967296 accessor 0, exit 0
// with another picture); a quaternion that is not a rotation sheared or scaled the node; a
// light's colour and intensity, each finite, overflowed once multiplied (NaN samples).
TEST(GltfValidFiles, NumbersPastWhatTheReaderHoldsAreRefused) {
  const auto dir = test::temp_dir("gltf-numbers");
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& d) { d["nodes"][0]["mesh"] = 4294967295u; },
       "nodes[0].mesh: expected a whole number from 0 to 2147483647, got 4294967295"},
      {[](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 4294967296u; },
       "meshes[0].primitives[0].attributes: expected an object of whole numbers from 0 to 2147483647"},
      {[](json& d) {
         d["scenes"][0]["nodes"] = {0, 2147483648u};
       },
       "scenes[0].nodes: expected an array"},
      {[](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 4294967300.0; },
       "meshes[0].primitives[0].mode: expected a whole number from 0 to 2147483647"},
      {[](json& d) { d["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 4294967296u; },
       "nodes[1].extensions.KHR_lights_punctual.light: expected a whole number from 0 to 2147483647"},
      {[](json& d) {
         d["nodes"][0]["rotation"] = {0, 0, 0, 0};
       },
       "nodes[0].rotation: is not a unit quaternion (its length is 0.000000)"},
      {[](json& d) {
         d["nodes"][0]["rotation"] = {2, 0, 0, 0};
       },
       "nodes[0].rotation: is not a unit quaternion"},
      {[](json& d) {
         d["extensions"]["KHR_lights_punctual"]["lights"] = {
             {{"type", "point"}, {"intensity", 1e29}, {"color", {1e20, 1, 1}}}};
         d["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 0;
       },
       "extensions.KHR_lights_punctual.lights[0]: color x intensity must be below 1e30"},
  };
  for (const auto& [edit, expected] : cases) {
    json doc = test::triangle_gltf();
    edit(doc);
    expect_refused(test::write_gltf(dir / "n.gltf", doc), expected);
  }
  // A rounded quaternion, as exporters write them, is taken as written.
  json doc = test::triangle_gltf();
  doc["nodes"][0]["rotation"] = {0, 0, 0.70710678, 0.7071075};
  EXPECT_NO_THROW(load_scene(test::write_gltf(dir / "r.gltf", doc)));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
