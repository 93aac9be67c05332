// Textures: texel centres read back exactly, bilinear weights, wrap and clamp, sRGB
// decoding, a checker on a quad seen head-on lands on the predicted pixels, and bad image
// inputs are errors that name the file and key.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <fstream>

#include "image/image_io.h"
#include "io/input_error.h"
#include "kernel/shading/surface.h"
#include "render/render_cpu.h"
#include "scene/texture_loader.h"
#include "test_util.h"

namespace tracer {
namespace {

// A scene file in `dir` whose one material's albedo is `colour` (JSON).
Scene textured_scene(const std::filesystem::path& dir, const std::string& colour) {
  const std::string json = R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 1], "to": [0, 0, 0], "vfov": 90},
    "film": {"width": 64, "height": 64}, "render": {"integrator": "albedo", "sampler": "center"},
    "materials": {"m": {"type": "lambert", "albedo": )" +
                           colour + R"(}},
    "shapes": [{"type": "quad", "corner": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "m"}]})";
  return load_scene_text(json, (dir / "scene.json").string());
}

// A 4 x 4 float image with distinct texels (power-of-two sizes, so texel-centre
// coordinates are exact floats).
Image test_image() {
  Image img{4, 4, {}};
  for (uint32_t i = 0; i < 16; ++i) img.rgb.insert(img.rgb.end(), {0.1f * i, 1.0f + i, 0.37f * (i % 5)});
  return img;
}

TEST(Textures, TexelCentresReadBackExactly) {
  const auto dir = test::temp_dir("tex-centres");
  const Image img = test_image();
  write_image(img, (dir / "t.exr").string());
  const Scene scene = textured_scene(dir, R"({"texture": "t.exr"})");
  ASSERT_EQ(scene.textures.size(), 1u);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      const Vec3 v =
          sample_texture(scene.textures.data(), scene.texels.data(), 0, (x + 0.5f) / 4.0f, 1.0f - (y + 0.5f) / 4.0f);
      const float* e = &img.rgb[3 * (y * 4 + x)];
      EXPECT_EQ(v.x, e[0]) << x << "," << y;
      EXPECT_EQ(v.y, e[1]) << x << "," << y;
      EXPECT_EQ(v.z, e[2]) << x << "," << y;
    }
  std::filesystem::remove_all(dir);
}

TEST(Textures, BilinearWeightsWrapAndClamp) {
  const auto dir = test::temp_dir("tex-bilinear");
  const Image img = test_image();
  write_image(img, (dir / "t.exr").string());
  const Scene repeat = textured_scene(dir, R"({"texture": "t.exr"})");
  const Scene clamp = textured_scene(dir, R"({"texture": "t.exr", "wrap": "clamp"})");
  const auto at = [](const Scene& s, float u, float v) {
    return sample_texture(s.textures.data(), s.texels.data(), 0, u, v);
  };
  const auto texel = [&](int x, int y) { return img.rgb[3 * (y * 4 + x) + 1]; };  // green channel
  // Halfway between texel centres (1, 0) and (2, 0): weights 1/2 and 1/2.
  EXPECT_FLOAT_EQ(at(repeat, 2.0f / 4.0f, 1.0f - 0.5f / 4.0f).y, 0.5f * texel(1, 0) + 0.5f * texel(2, 0));
  // A quarter of the way from (1, 1) to (2, 2) on both axes.
  const float q = 0.25f, w00 = (1 - q) * (1 - q), w10 = q * (1 - q), w01 = (1 - q) * q, w11 = q * q;
  EXPECT_FLOAT_EQ(at(repeat, (1.5f + q) / 4.0f, 1.0f - (1.5f + q) / 4.0f).y,
                  w00 * texel(1, 1) + w10 * texel(2, 1) + w01 * texel(1, 2) + w11 * texel(2, 2));
  // Repeat: u and u + 1 agree; between the last and first column the filter wraps.
  EXPECT_EQ(at(repeat, 0.3f, 0.4f).y, at(repeat, 1.3f, 0.4f).y);
  EXPECT_FLOAT_EQ(at(repeat, 0.0f, 1.0f - 0.5f / 4.0f).y, 0.5f * texel(3, 0) + 0.5f * texel(0, 0));
  // Clamp: beyond the edge is the edge texel.
  EXPECT_EQ(at(clamp, 1.7f, 1.0f - 0.5f / 4.0f).y, texel(3, 0));
  EXPECT_EQ(at(clamp, -3.0f, 1.0f - 0.5f / 4.0f).y, texel(0, 0));
  std::filesystem::remove_all(dir);
}

TEST(Textures, MirroredRepeatReadsEveryOtherCopyReversed) {
  // glTF's MIRRORED_REPEAT (along u only here; v clamps): u in [1, 2] reads 2 - u, u in
  // [-1, 0] reads -u, and the filter at the edge of a copy reads its edge texel twice.
  const auto dir = test::temp_dir("tex-mirror");
  const Image img = test_image();
  write_image(img, (dir / "t.exr").string());
  Scene s = textured_scene(dir, R"({"texture": "t.exr"})");
  s.textures[0].wrap_u = TextureWrap::Mirror;
  s.textures[0].wrap_v = TextureWrap::Clamp;
  const auto at = [&](float u, float v) { return sample_texture(s.textures.data(), s.texels.data(), 0, u, v).y; };
  const auto texel = [&](int x, int y) { return img.rgb[3 * (y * 4 + x) + 1]; };
  for (const float u : {0.1f, 0.375f, 0.8f}) {
    EXPECT_FLOAT_EQ(at(2.0f - u, 0.4f), at(u, 0.4f)) << u;  // within the rounding of 2 - u
    EXPECT_FLOAT_EQ(at(-u, 0.4f), at(u, 0.4f)) << u;
    EXPECT_FLOAT_EQ(at(4.0f + u, 0.4f), at(u, 0.4f)) << u;
  }
  EXPECT_EQ(at(1.0f, 1.0f - 0.5f / 4.0f), texel(3, 0));  // between column 3 and its mirror image
  EXPECT_EQ(at(0.0f, 1.0f - 0.5f / 4.0f), texel(0, 0));
  EXPECT_EQ(at(0.3f, 1.7f), at(0.3f, 1.0f));  // v clamps
  std::filesystem::remove_all(dir);
}

TEST(Textures, EightBitImagesAreSrgbDecoded) {
  const auto dir = test::temp_dir("tex-srgb");
  OIIO::ImageBuf buf(OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8));
  const float grey[3] = {128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f};
  OIIO::ImageBufAlgo::fill(buf, grey);
  ASSERT_TRUE(buf.write((dir / "g.png").string()));
  const Scene scene = textured_scene(dir, R"({"texture": "g.png"})");
  EXPECT_NEAR(scene.texels[0], 0.2158605, 1e-6);  // sRGB 128 is linear 0.2158605
  EXPECT_NEAR(scene.materials[0].albedo.x, 0.2158605, 1e-6) << "the colour holds the texture's mean";
  std::filesystem::remove_all(dir);
}

// Seen head-on through a 90-degree pinhole, quad parameter alpha at pixel column x is
// (x + 0.5) / 64 and beta at row y is 1 - (y + 0.5) / 64: with 8 squares per unit the
// square of pixel (x, y) is (x / 8, 7 - y / 8).
TEST(Textures, CheckerOnAQuadHeadOnLandsOnThePredictedPixels) {
  const auto dir = test::temp_dir("tex-checker");
  const Scene scene = textured_scene(dir, R"({"checker": {"scale": 8, "even": [1, 0, 0], "odd": [0, 0, 1]}})");
  RenderStats stats;
  const Image img = render_cpu(scene, 1, stats);
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const bool even = ((x / 8) + (7 - y / 8)) % 2 == 0;
      const float* p = &img.rgb[3 * (y * 64 + x)];
      ASSERT_EQ(p[0], even ? 1.0f : 0.0f) << x << "," << y;
      ASSERT_EQ(p[2], even ? 0.0f : 1.0f) << x << "," << y;
    }
  std::filesystem::remove_all(dir);
}

TEST(Textures, BadImagesAreErrorsNamingFileAndKey) {
  const auto dir = test::temp_dir("tex-bad");
  OIIO::ImageBuf two(OIIO::ImageSpec(2, 2, 2, OIIO::TypeDesc::UINT8));
  ASSERT_TRUE(two.write((dir / "two.png").string()));
  std::ofstream(dir / "junk.png") << "not a png";
  const struct {
    std::string colour, expected;
  } cases[] = {
      {R"({"texture": "missing.png"})", "materials.m.albedo.texture: image"},
      {R"({"texture": "two.png"})", "expected 1, 3 or 4 channels, got 2"},
      {R"({"texture": "junk.png"})", "cannot read image"},
      {R"({"texture": "two.png", "wrap": "mirror"})", "materials.m.albedo.wrap: expected \"repeat\" or \"clamp\""},
      {R"({"checker": {"scale": 0, "even": [1, 1, 1], "odd": [0, 0, 0]}})",
       "materials.m.albedo.checker.scale: must be > 0"},
      {R"({"gradient": 1})", "materials.m.albedo: expected [r, g, b]"},
  };
  for (const auto& c : cases) {
    try {
      textured_scene(dir, c.colour);
      ADD_FAILURE() << "accepted " << c.colour;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

// The sphere's u wraps from 1 back to 0 where atan2(z, x) jumps from pi to -pi; with a
// repeating texture the filter blends the last and first columns there: no crack.
TEST(Textures, SphereUvSeamHasNoCrack) {
  const auto dir = test::temp_dir("tex-seam");
  Image img{64, 4, {}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 64; ++x) {
      const float c = 0.5f + 0.5f * std::sin(2.0f * float(M_PI) * (x + 0.5f) / 64.0f);
      img.rgb.insert(img.rgb.end(), {c, c, c});
    }
  write_image(img, (dir / "periodic.exr").string());
  const std::string json = R"({"format": "tracer-scene/1", "camera": {"from": [-3, 0, 0], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 8}, "materials": {"m": {"type": "lambert", "albedo": {"texture": "periodic.exr"}}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
  const Scene scene = load_scene_text(json, (dir / "s.json").string());
  const SceneView view = scene.view();
  for (const float y : {-0.5f, 0.0f, 0.5f}) {
    // Two rays hitting the sphere on either side of the seam (x < 0, z = -+1e-4).
    const Ray above = {{-3, y, 1e-4f}, {1, 0, 0}}, below = {{-3, y, -1e-4f}, {1, 0, 0}};
    Surface sa = surface_at(view, above, trace_closest(view, above, kInfinity));
    Surface sb = surface_at(view, below, trace_closest(view, below, kInfinity));
    EXPECT_GT(std::abs(sa.u - sb.u), 0.99f) << "the two points straddle the seam";
    const float ca = material_at(view, sa).albedo.x, cb = material_at(view, sb).albedo.x;
    EXPECT_NEAR(ca, cb, 1e-3f) << "crack at the seam, y = " << y;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
