// Hostile glTF files and images whose cost was out of proportion to their size: one external
// file read once per buffer naming it, triangles of zero area escaping the triangle limit, a
// quadratic list of the parts left out, image headers declaring more pixels than their data
// can hold, a JPEG cut short accepted as grey, an undecodable data URI echoed whole, bare
// nodes that the glTF reader holds in 456 bytes each.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include "gltf_builder.h"
#include "hostile_input.h"
#include "image/image_io.h"
#include "sanitizer.h"
#include "scene/gltf_reader_memory.h"
#include "scene/scene_loader.h"

namespace tracer {
namespace {

using nlohmann::json;

std::string render_args(const fs::path& file, const fs::path& out) {
  return "render " + file.string() + " --width 4 --height 3 --spp 1 --quiet -o " + out.string();
}

// 100 buffers naming one 16 MB file: tinygltf read it once per buffer (1.6 GB); shared now,
// the render fits in a 1.2 GB address space.
TEST_F(HostileInput, BuffersNamingOneFileReadItOnce) {
#if TRACER_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "ulimit -v cannot hold an AddressSanitizer build (its shadow memory reserves terabytes)";
#endif
  json doc = test::triangle_gltf();
  std::string bin =
      test::bytes_of(std::vector<float>{-1, -1, 0, 1, -1, 0, 0, 1, 0}) + test::bytes_of(std::vector<uint16_t>{0, 1, 2});
  bin.resize(16u << 20, '\0');
  write(dir_ / "one.bin", bin);
  doc["buffers"] = json::array();
  doc["bufferViews"] = json::array();
  for (int i = 0; i < 100; ++i) {
    doc["buffers"].push_back(
        {{"byteLength", bin.size() - static_cast<size_t>(i)}, {"uri", i % 2 ? "one.bin" : "./one.bin"}});
    doc["bufferViews"].push_back({{"buffer", i}, {"byteOffset", 0}, {"byteLength", 36}});
  }
  doc["bufferViews"][1] = {{"buffer", 1}, {"byteOffset", 36}, {"byteLength", 6}};
  test::write_gltf(dir_ / "shared.gltf", doc);
  std::string output;
  EXPECT_EQ(test::run_command("ulimit -v 1200000 && timeout 60 " + std::string(TRACER_BINARY) + " " +
                                  render_args(dir_ / "shared.gltf", dir_ / "out.png"),
                              &output),
            0)
      << output;
}

// Every triangle placed counts against the 2^24 of a glTF file, those of zero area too: nine
// instances of 2^21 triangles at the origin (a position accessor without a buffer view is all
// zeros) were built, tested and left out, uncounted (2.1e9 of them loaded for 12 minutes).
TEST_F(HostileInput, TrianglesOfZeroAreaCountAgainstTheTriangleLimit) {
  json doc = test::triangle_gltf();
  doc["accessors"].push_back({{"componentType", 5126}, {"count", 3u << 21}, {"type", "VEC3"}});
  doc["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 2}}}}}}});
  for (int i = 0; i < 9; ++i) {
    doc["nodes"].push_back({{"mesh", 1}});
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
  }
  try {
    load_scene(test::write_gltf(dir_ / "zero.gltf", doc));
    ADD_FAILURE() << "loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("would place more than 2^24 triangles"), std::string::npos) << e.what();
  }
}

// 160,000 points primitives (6 MB) are left out, each listed once: the list was deduplicated
// by a linear search (52 s); within the 30 s limit now.
TEST_F(HostileInput, ManyPartsLeftOutAreListedInLinearTime) {
  json doc = test::triangle_gltf();
  json& prims = doc["meshes"][0]["primitives"];
  for (int i = 0; i < 160000; ++i) prims.push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 0}});
  test::write_gltf(dir_ / "points.gltf", doc);
  std::string output;
  EXPECT_EQ(run_limited(render_args(dir_ / "points.gltf", dir_ / "out.png"), output), 0) << output.substr(0, 1000);
}

// A data URI that does not decode was refused in tinygltf's words, quoting the whole URI (a 4 MB
// file, a 4 MB line); now by its JSON path, in a line.
TEST_F(HostileInput, AnUndecodableDataUriIsNamedByItsPath) {
  json doc = test::triangle_gltf();
  doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + std::string(1 << 20, '!');
  try {
    load_scene(test::write_gltf(dir_ / "uri.gltf", doc));
    ADD_FAILURE() << "loaded";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_LT(what.size(), 1000u);
    EXPECT_NE(what.find("buffers[0].uri: a data URI whose data does not decode"), std::string::npos)
        << what.substr(0, 1000);
  }
}

// Bare nodes cost the reader a struct each (sizeof(tinygltf::Node)), 20-50 times what the file
// writes for them; a file whose bound passes half the memory limit is refused before the
// reader runs, naming the array. Here a limit of 4 MB against 10,000 nodes (the bound: 10,000
// x 456 x 3 bytes).
TEST_F(HostileInput, ElementsTheReaderCannotHoldAreRefusedByTheirArray) {
  json doc = test::triangle_gltf();
  for (int i = 0; i < 10000; ++i) doc["nodes"].push_back(json::object());
  const GltfReaderBytes bytes = gltf_reader_bytes(doc);
  EXPECT_EQ(bytes.largest, "nodes");
  EXPECT_EQ(bytes.largest_count, doc["nodes"].size());
  EXPECT_GE(bytes.total, 10000u * 456u);
  try {
    check_gltf_reader_memory(doc, {4u << 20, "a test's limit"}, "many.gltf");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("many.gltf: nodes: 10002 elements"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("more than half of a test's limit"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_gltf_reader_memory(doc, {64u << 20, "a test's limit"}, "many.gltf"));
  // A real file's bound: the Cornell box (two buffers' bytes and a few dozen elements).
  const Json box = parse_json_text(test::read_file(test::source_path("scenes/gltf/cornell-box.gltf")), "box");
  EXPECT_LT(gltf_reader_bytes(box).total, 1u << 20);
}

std::string encoded(const std::string& format) {
  const Image image = test::image_from(64, 64, [](uint32_t x, uint32_t y) { return Vec3{x / 64.0f, y / 64.0f, 0.5f}; });
  const fs::path file = test::temp_dir("encoded") / ("i." + format);
  write_image(image, file.string());
  std::string bytes = test::read_file(file);
  fs::remove_all(file.parent_path());
  return bytes;
}

void expect_image_refused(const std::string& bytes, const std::string& format, const std::string& expected) {
  try {
    read_image_pixels_from_memory(std::vector<unsigned char>(bytes.begin(), bytes.end()), format, "img", 4);
    ADD_FAILURE() << "read: " << expected;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

// A header's pixels against the data that must hold them: a 69-byte PNG declaring 8192^2
// pixels had libpng allocate 760 MB before it refused; a JPEG cut short (its scan missing) was
// decoded as grey and accepted; one declaring 16000^2 pixels in a few bytes took minutes.
TEST(HostileImages, DeclaredPixelsMustFitTheirData) {
  const std::string png = encoded("png"), jpeg = encoded("jpg");
  EXPECT_NO_THROW(read_image_pixels_from_memory(std::vector<unsigned char>(png.begin(), png.end()), "png", "p", 4));
  EXPECT_NO_THROW(read_image_pixels_from_memory(std::vector<unsigned char>(jpeg.begin(), jpeg.end()), "jpg", "j", 4));
  // A PNG: signature, IHDR of 8192 x 8192 RGB, an IDAT of 8 bytes, IEND (CRCs unchecked here).
  const auto be32 = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  const std::string tiny_png = std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR" + be32(8192) + be32(8192) +
                               std::string("\x08\x02\x00\x00\x00", 5) + be32(0) + be32(8) + "IDAT" +
                               std::string(8, '\0') + be32(0) + be32(0) + "IEND" + be32(0);
  expect_image_refused(tiny_png, "png", "its PNG chunk IDAT holds 8 bytes; the 8192x8192 pixels");
  // The JPEG cut inside its scan, and the whole JPEG with its frame header declaring 16000^2.
  const size_t scan = jpeg.find("\xff\xda");
  ASSERT_NE(scan, std::string::npos);
  expect_image_refused(jpeg.substr(0, scan + 40), "jpg", "its JPEG data is cut short: no end-of-image marker");
  std::string huge = jpeg;
  const size_t frame = huge.find("\xff\xc0");
  ASSERT_NE(frame, std::string::npos);
  huge[frame + 5] = huge[frame + 7] = char(16000 >> 8);
  huge[frame + 6] = huge[frame + 8] = char(16000 & 0xff);
  expect_image_refused(huge, "jpg", "pixels its header declares, fewer than one bit per 8x8 block");
}

}  // namespace
}  // namespace tracer
