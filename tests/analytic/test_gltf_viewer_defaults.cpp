// glTF files shown as a viewer shows them (docs/gltf.md): emission adds to the surface's
// reflection (closed form under the neutral sky), an emissive texture glows only where it is
// bright, emitting triangles stay lights, the neutral sky stays whatever the file emits, and
// the default camera fills the frame with the model whatever its shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "gltf_builder.h"
#include "image/image_io.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A quad [-1, 1]^2 at z = 0 facing +z, its uvs spanning the texture, seen head-on by the
// file's camera at z = 3, material 0; no lights but what the material emits.
json quad_gltf() {
  test::GltfDoc g;
  const int p = g.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3, true);
  const int n = g.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int uv = g.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  g.push("meshes", {{"primitives",
                     {{{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", uv}}},
                       {"indices", g.indices({0, 1, 2, 0, 2, 3})},
                       {"material", 0}}}}});
  g.push("nodes", {{"mesh", 0}});
  g.push("cameras", {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.0}, {"znear", 0.1}}}});
  g.push("nodes", {{"camera", 0}, {"translation", {0, 0, 3}}});
  g.doc["scenes"][0]["nodes"] = {0, 1};
  g.doc["extensionsUsed"] = {"KHR_materials_specular", "KHR_materials_emissive_strength"};
  // A Lambert surface (no specular layer) of albedo 0.5, 0.25, 0.125, emitting 2 x (1, 0.5, 0.25).
  g.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 0.125, 1}}, {"metallicFactor", 0}}},
                         {"emissiveFactor", {1, 0.5, 0.25}},
                         {"extensions",
                          {{"KHR_materials_specular", {{"specularFactor", 0}}},
                           {"KHR_materials_emissive_strength", {{"emissiveStrength", 2}}}}}}};
  return g.finish();
}

Image render_file(const std::string& file, uint32_t spp) {
  RenderOverrides ov;
  ov.width = 16;
  ov.height = 16;
  ov.spp = spp;
  ov.max_depth = 1;
  RenderStats stats;
  return render_cpu(load_scene(file, ov), 1, stats);
}

Vec3 pixel(const Image& img, uint32_t x, uint32_t y) {
  const size_t i = (size_t{y} * img.width + x) * 3;
  return {img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]};
}

TEST(GltfViewerDefaults, EmissionAddsToTheReflectionOfTheNeutralSky) {
  // Under a sky of radiance 1 a Lambert surface of albedo a reflects radiance a exactly (each
  // cosine-sampled direction returns a x 1), so every pixel on the quad is emission + albedo:
  // (2.5, 1.25, 0.625). Emission in place of the reflection gave (2, 1, 0.5).
  const auto dir = test::temp_dir("emission-adds");
  const std::string file = test::write_gltf(dir / "q.gltf", quad_gltf());
  const Scene s = load_scene(file);
  EXPECT_EQ(s.background.radiance, (Vec3{1, 1, 1}));  // it emits, and keeps the viewer's sky
  ASSERT_EQ(s.light_table.size(), 2u);                // its two triangles are lights
  const Image img = render_file(file, 16);
  for (uint32_t y = 6; y < 10; ++y)
    for (uint32_t x = 6; x < 10; ++x) {
      const Vec3 c = pixel(img, x, y);
      EXPECT_NEAR(c.x, 2.5f, 1e-5f) << x << ", " << y;
      EXPECT_NEAR(c.y, 1.25f, 1e-5f) << x << ", " << y;
      EXPECT_NEAR(c.z, 0.625f, 1e-5f) << x << ", " << y;
    }
  fs::remove_all(dir);
}

TEST(GltfViewerDefaults, AnEmissiveTextureGlowsWhereItIsBrightAndReflectsEverywhere) {
  // The emissive texture is white on its left half and black on its right: the left half of
  // the quad shows emission + albedo, the right half the albedo alone.
  const auto dir = test::temp_dir("emissive-texture");
  write_image(test::image_from(8, 8,
                               [](uint32_t x, uint32_t) {
                                 return x < 4 ? Vec3{1, 1, 1} : Vec3{0, 0, 0};
                               }),
              (dir / "glow.png").string());
  json doc = quad_gltf();
  doc["images"] = {{{"uri", "glow.png"}}};
  doc["textures"] = {{{"source", 0}}};
  doc["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33071}}};
  doc["textures"][0]["sampler"] = 0;
  doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
  const Image img = render_file(test::write_gltf(dir / "q.gltf", doc), 16);
  EXPECT_NEAR(pixel(img, 5, 8).x, 2.5f, 1e-5f);   // a quarter in from the left
  EXPECT_NEAR(pixel(img, 10, 8).x, 0.5f, 1e-5f);  // a quarter in from the right
  EXPECT_NEAR(pixel(img, 10, 8).z, 0.125f, 1e-5f);
  fs::remove_all(dir);
}

TEST(GltfViewerDefaults, ABlackLambertEmitterIsTheEmissiveMaterial) {
  // A lamp that reflects nothing: the emissive material, the same light without a BSDF.
  const auto dir = test::temp_dir("black-emitter");
  json doc = quad_gltf();
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0, 0, 0, 1};
  Scene s = load_scene(test::write_gltf(dir / "q.gltf", doc));
  EXPECT_EQ(s.materials[0].kind, MaterialKind::Emissive);
  EXPECT_EQ(s.materials[0].radiance, (Vec3{2, 1, 0.5f}));
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.25, 0.125, 1};
  s = load_scene(test::write_gltf(dir / "q.gltf", doc));
  EXPECT_EQ(s.materials[0].kind, MaterialKind::Lambert);
  EXPECT_EQ(s.materials[0].radiance, (Vec3{2, 1, 0.5f}));
  fs::remove_all(dir);
}

// A box of the given size about (3, -2, 5) (two triangles a face), without a camera.
json box_gltf(float sx, float sy, float sz) {
  test::GltfDoc g;
  std::vector<float> p;
  for (int k = 0; k < 8; ++k)
    p.insert(p.end(), {3 + sx * ((k & 1) ? 0.5f : -0.5f), -2 + sy * ((k & 2) ? 0.5f : -0.5f),
                       5 + sz * ((k & 4) ? 0.5f : -0.5f)});
  const std::vector<uint32_t> faces = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                                       2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
  g.push("meshes", {{"primitives",
                     {{{"attributes", {{"POSITION", g.floats(p, "VEC3", 3, true)}}}, {"indices", g.indices(faces)}}}}});
  g.push("nodes", {{"mesh", 0}});
  g.doc["scenes"][0]["nodes"] = {0};
  return g.finish();
}

TEST(GltfViewerDefaults, TheDefaultCameraFillsTheFrameWithTheModel) {
  // Seen by the albedo view (0 where a ray misses), the model's pixels span 80-92 % of the
  // frame along the side that binds (the camera fits 90 % of it) and never touch its border,
  // whether the model is long, tall, deep or flat.
  const auto dir = test::temp_dir("framing");
  const std::vector<std::array<float, 3>> sizes = {
      {10, 0.5, 0.5}, {0.5, 10, 0.5}, {0.5, 0.5, 10}, {4, 0.05, 4}, {1, 1, 1}};
  for (const auto& [sx, sy, sz] : sizes) {
    RenderOverrides ov;
    ov.width = 64;
    ov.height = 48;
    ov.spp = 1;
    ov.sampler = SamplerKind::Center;
    ov.integrator = IntegratorKind::Albedo;
    RenderStats stats;
    const Image img = render_cpu(load_scene(test::write_gltf(dir / "box.gltf", box_gltf(sx, sy, sz)), ov), 1, stats);
    uint32_t x0 = img.width, x1 = 0, y0 = img.height, y1 = 0;
    for (uint32_t y = 0; y < img.height; ++y)
      for (uint32_t x = 0; x < img.width; ++x)
        if (pixel(img, x, y).x > 0.0f)
          x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    const std::string size = std::to_string(sx) + " x " + std::to_string(sy) + " x " + std::to_string(sz);
    ASSERT_LE(x0, x1) << size << ": the model is not in the frame";
    EXPECT_GT(x0, 0u) << size;
    EXPECT_LT(x1, img.width - 1) << size;
    EXPECT_GT(y0, 0u) << size;
    EXPECT_LT(y1, img.height - 1) << size;
    const double fill = std::max(double(x1 - x0 + 1) / img.width, double(y1 - y0 + 1) / img.height);
    EXPECT_GE(fill, 0.8) << size;
    EXPECT_LE(fill, 0.92) << size;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
