// glTF textures (docs/gltf.md): the metallic-roughness texture scales the factors (G the
// roughness, B the metallic) exactly: a white texture leaves the material as its factors, a
// zero channel zeroes its factor; the base colour texture's texels are sRGB-decoded and, once
// filtered, multiplied by the factor, so one image under many tints is stored once; the normal
// map's scale applies to the filtered normal; alphaMode MASK
// cuts the quad out where its base colour texture's alpha is below the cutoff, BLEND of alpha
// 0 leaves nothing to hit.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <fstream>

#include "gltf_builder.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A quad (two triangles) facing the camera with uvs, material 0 metal_rough; a 2x2 texture
// image "t.png" beside the file when `with_texture`.
json textured_quad() {
  const std::vector<float> p = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::vector<float> uv = {0, 1, 1, 1, 1, 0, 0, 0};
  const std::vector<uint16_t> idx = {0, 1, 2, 0, 2, 3};
  const std::string buffer = test::bytes_of(p) + test::bytes_of(uv) + test::bytes_of(idx);
  json doc = test::triangle_gltf();
  doc["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", test::data_uri(buffer)}};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
                        {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}};
  doc["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                      {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
                      {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}};
  doc["meshes"][0]["primitives"][0] = {
      {"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}};
  doc["materials"][0]["pbrMetallicRoughness"] = {
      {"baseColorFactor", {0.8, 0.6, 0.4, 1}}, {"metallicFactor", 0.7}, {"roughnessFactor", 0.4}};
  doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 20}}};
  doc["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  return doc;
}

class GltfTextures : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("gltf-textures"); }
  void TearDown() override { fs::remove_all(dir_); }
  void write_png(const std::string& name, Vec3 c) {
    write_image(test::image_from(2, 2, [&](uint32_t, uint32_t) { return c; }), (dir_ / name).string());
  }
  Image render(const json& doc) {
    RenderOverrides ov;
    ov.width = 12;
    ov.height = 6;
    ov.spp = 4;
    RenderStats stats;
    return render_cpu(load_scene(test::write_gltf(dir_ / "t.gltf", doc), ov), 1, stats);
  }
  static bool same(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * 4) == 0;
  }
  static json with_texture(json doc, const std::string& slot, const std::string& image) {
    doc["images"] = {{{"uri", image}}};
    doc["textures"] = {{{"source", 0}}};
    if (slot == "normalTexture")
      doc["materials"][0][slot] = {{"index", 0}, {"scale", 0.5}};
    else
      doc["materials"][0]["pbrMetallicRoughness"][slot] = {{"index", 0}};
    return doc;
  }
  fs::path dir_;
};

TEST_F(GltfTextures, AMetallicRoughnessTextureScalesTheFactors) {
  const json plain = textured_quad();
  write_png("white.png", {1, 1, 1});
  const Image factors = render(plain);
  EXPECT_TRUE(same(factors, render(with_texture(plain, "metallicRoughnessTexture", "white.png"))));
  // G = 0: roughness 0; B = 0: metallic 0 (R, occlusion, is not read).
  write_png("no-roughness.png", {1, 0, 1});
  json smooth = plain;
  smooth["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0;
  EXPECT_TRUE(same(render(smooth), render(with_texture(plain, "metallicRoughnessTexture", "no-roughness.png"))));
  EXPECT_FALSE(same(render(smooth), factors));
  write_png("no-metal.png", {0, 1, 0});
  json dielectric = plain;
  dielectric["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0;
  EXPECT_TRUE(same(render(dielectric), render(with_texture(plain, "metallicRoughnessTexture", "no-metal.png"))));
}

TEST_F(GltfTextures, BaseColourTexelsAreDecodedAndMultipliedByTheFactor) {
  write_png("white.png", {1, 1, 1});
  const Scene s =
      load_scene(test::write_gltf(dir_ / "t.gltf", with_texture(textured_quad(), "baseColorTexture", "white.png")));
  const Material& m = s.materials[0];
  ASSERT_NE(m.texture[kSlotAlbedo], kNoTexture);
  const Texture& t = s.textures[m.texture[kSlotAlbedo]];
  EXPECT_EQ(s.texels[t.offset], 1.0f);  // sRGB 255
  // 1 x the factor, wherever it is read.
  for (const float u : {0.1f, 0.5f, 0.93f}) {
    const Vec3 c = sample_texture(s.textures.data(), s.texels.data(), m.texture[kSlotAlbedo], u, 0.3f);
    EXPECT_EQ(c, Vec3(0.8f, 0.6f, 0.4f));
  }
  EXPECT_EQ(m.albedo, Vec3(0.8f, 0.6f, 0.4f));  // the texture's mean
  // A white texture equals no texture, bit for bit.
  EXPECT_TRUE(same(render(textured_quad()), render(with_texture(textured_quad(), "baseColorTexture", "white.png"))));
}

// 24 materials tint one image 24 ways: its texels are stored once, and each material reads
// its own factor times the texel (a grey, its 8-bit sRGB value decoded).
TEST_F(GltfTextures, OneImageUnderManyTintsIsStoredOnce) {
  write_png("grey.png", {0.5f, 0.5f, 0.5f});
  json doc = with_texture(textured_quad(), "baseColorTexture", "grey.png");
  const json first = doc["materials"][0];
  constexpr int kTints = 24;
  doc["materials"] = json::array();
  for (int i = 0; i < kTints; ++i) {
    json m = first;
    m["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, i / 24.0, 0.25, 1.0};
    doc["materials"].push_back(m);
  }
  doc["meshes"][0]["primitives"] = json::array();
  for (int i = 0; i < kTints; ++i) {
    doc["meshes"][0]["primitives"].push_back(
        {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", i}});
  }
  const Scene s = load_scene(test::write_gltf(dir_ / "t.gltf", doc));
  EXPECT_EQ(s.texels.size(), 2u * 2u * 3u);
  const float grey = s.texels[0];
  EXPECT_NEAR(grey, 0.5f, 4e-3f);  // within the 8-bit sRGB step
  size_t tinted = 0;
  for (const Material& m : s.materials) {
    if (m.texture[kSlotAlbedo] == kNoTexture) continue;
    const Vec3 c = sample_texture(s.textures.data(), s.texels.data(), m.texture[kSlotAlbedo], 0.4f, 0.6f);
    const Vec3 factor = s.textures[m.texture[kSlotAlbedo]].times;
    EXPECT_EQ(factor.x, 1.0f);
    EXPECT_EQ(factor.z, 0.25f);
    EXPECT_EQ(c, grey * factor);
    EXPECT_EQ(m.albedo, grey * factor);
    ++tinted;
  }
  EXPECT_EQ(tinted, size_t{kTints});
}

TEST_F(GltfTextures, TheNormalMapsScaleAppliesToTheFilteredNormal) {
  write_png("tilted.png", {1, 0.5f, 1});  // x = +1 before the scale
  const Scene s =
      load_scene(test::write_gltf(dir_ / "t.gltf", with_texture(textured_quad(), "normalTexture", "tilted.png")));
  const uint32_t map = s.materials[0].normal_map;
  EXPECT_EQ(s.texels[s.textures[map].offset], 1.0f);  // stored as decoded
  const Vec3 c = sample_texture(s.textures.data(), s.texels.data(), map, 0.5f, 0.5f);
  EXPECT_EQ(c.x, 0.75f);  // ((2 x 1 - 1) x 0.5 + 1) / 2
  EXPECT_EQ(c.z, 1.0f);   // z keeps its value
}

// A 2 x 1 RGBA image: the left texel white and transparent, the right one white and opaque.
void write_half_transparent_png(const fs::path& path) {
  const float texels[8] = {1, 1, 1, 0, 1, 1, 1, 1};
  const auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(2, 1, 4, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, texels));
  ASSERT_TRUE(out->close());
}

// The quad's u grows with x: masked at the cutoff 0.5, its left half (u < 0.5) is open and shows
// the neutral sky (radiance 1, exactly), its right half is drawn; the texture's alpha is read
// straight (not premultiplied), so the opaque half keeps its colour.
TEST_F(GltfTextures, AlphaModeMaskCutsTheQuadOutByTheBaseColoursAlpha) {
  write_half_transparent_png(dir_ / "half.png");
  json doc = with_texture(textured_quad(), "baseColorTexture", "half.png");
  doc["materials"][0]["alphaMode"] = "MASK";
  const Scene s = load_scene(test::write_gltf(dir_ / "t.gltf", doc));
  const Material& m = s.materials[0];
  ASSERT_EQ(m.alpha_mode, AlphaMode::Mask);
  EXPECT_EQ(m.alpha_cutoff, 0.5f);
  ASSERT_NE(m.alpha_map, kNoTexture);
  const Texture& a = s.textures[m.alpha_map];
  EXPECT_EQ(s.texels[a.offset], 0.0f);
  EXPECT_EQ(s.texels[a.offset + 3], 1.0f);
  // The opaque texel's colour is read straight (1, white), times the factor's 0.8.
  EXPECT_EQ(s.texels[s.textures[m.texture[kSlotAlbedo]].offset + 3], 1.0f);
  EXPECT_EQ(s.textures[m.texture[kSlotAlbedo]].times.x, 0.8f);
  const Image img = render(doc);
  const auto pixel = [&](uint32_t x, uint32_t y) { return img.rgb[3 * (size_t(y) * img.width + x)]; };
  EXPECT_EQ(pixel(5, 3), 1.0f) << "the open half shows the sky";
  EXPECT_NE(pixel(7, 3), 1.0f) << "the opaque half is drawn";
  json opaque = doc;
  opaque["materials"][0]["alphaMode"] = "OPAQUE";
  EXPECT_NE(render(opaque).rgb[3 * (3 * 12 + 5)], 1.0f) << "OPAQUE draws the whole quad";
}

TEST_F(GltfTextures, AlphaModeBlendOfAlphaZeroLeavesNothingToHit) {
  json doc = textured_quad();
  doc["materials"][0]["alphaMode"] = "BLEND";
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.8, 0.6, 0.4, 0};
  for (float v : render(doc).rgb) ASSERT_EQ(v, 1.0f);
}

// A glTF file placed 24 times by a JSON scene is read once, its textures decoded and stored
// once (each placement decoded and stored them again: a 1024^2 texture placed 24 times took
// about 500 MB); every placement draws it.
TEST_F(GltfTextures, AFilePlacedManyTimesStoresItsTexturesOnce) {
  write_png("t.png", {0.5f, 0.5f, 0.5f});
  test::write_gltf(dir_ / "t.gltf", with_texture(textured_quad(), "baseColorTexture", "t.png"));
  std::string shapes;
  for (int i = 0; i < 24; ++i)
    shapes += std::string(i ? ", " : "") + R"({"type": "gltf", "file": "t.gltf", "transform": [{"translate": [)" +
              std::to_string(3 * i) + ", 0, 0]}]}";
  std::ofstream(dir_ / "placed.json")
      << R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
            "film": {"width": 4, "height": 3}, "materials": {}, "shapes": [)" +
             shapes + "]}";
  const Scene once =
      load_scene(test::write_gltf(dir_ / "once.gltf", with_texture(textured_quad(), "baseColorTexture", "t.png")));
  const Scene placed = load_scene((dir_ / "placed.json").string());
  EXPECT_EQ(placed.textures.size(), once.textures.size());
  EXPECT_EQ(placed.texels.size(), once.texels.size());
  EXPECT_EQ(placed.primitives.size(), 24 * once.primitives.size());
}

// KHR_texture_transform's offset and scale are each finite, but baked into the uvs their sum
// left float's range: infinite coordinates, NaN samples and exit 0. Refused at the vertex.
TEST_F(GltfTextures, ATextureTransformThatOverflowsTheCoordinatesIsRefused) {
  write_png("t.png", {0.5f, 0.5f, 0.5f});
  json doc = with_texture(textured_quad(), "baseColorTexture", "t.png");
  doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_lights_punctual"};
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
      {"offset", {3e38, 0}}, {"scale", {3e38, 1}}};
  try {
    render(doc);
    ADD_FAILURE() << "rendered";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("attributes.TEXCOORD_0: vertex 1's coordinates leave float's range"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tracer
