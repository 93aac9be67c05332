// Cut-outs (kernel/accel/alpha_test.h) against closed forms: a Lambert floor lit by a sun
// straight down through a screen masked by a checker (alpha 0 or 1 per cell, cutoff 0.5)
// is lit exactly under the open cells and black under the others, pixel by pixel; camera rays
// through a masked quad see the background exactly where the quad is open; a blended screen of
// alpha a passes (1 - a) of the sun in expectation, all of it at a = 0 and none at a = 1; and
// every structure keeps the same hits, so a scene of masked and blended spheres, quads and
// triangles renders bit for bit the same through each. The keys refuse what they cannot mean.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "kernel/camera/camera.h"
#include "options/enum_names.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

// A 4 x 4 checker of alpha 1 (even cells) and 0 (odd ones) in dir/mask.png.
void write_checker_mask(const std::filesystem::path& dir) {
  write_image(test::image_from(4, 4,
                               [](uint32_t x, uint32_t y) {
                                 const float a = (x + y) % 2 == 0 ? 1.0f : 0.0f;
                                 return Vec3{a, a, a};
                               }),
              (dir / "mask.png").string());
}

// Whether texture coordinates (u, v) of the checker are open (alpha 0), and how far they lie
// from a cell's edge, in cells: the filter ramps between texel centres, crossing the cutoff
// 0.5 exactly on the edges.
bool checker_open(float u, float v, float& edge_distance) {
  const float x = u * 4.0f, y = (1.0f - v) * 4.0f;  // texel space: row 0 at the top
  edge_distance = std::min(std::abs(x - std::round(x)), std::abs(y - std::round(y)));
  return (int(std::floor(x)) + int(std::floor(y))) % 2 != 0;
}

// Where the centre ray of pixel (x, y) meets the plane y = height.
Vec3 pixel_on_plane(const Scene& scene, uint32_t x, uint32_t y, float height) {
  const Ray r = camera_ray(scene.camera, x + 0.5f, y + 0.5f, 0.5f, 0.5f);
  return r.origin + r.dir * ((height - r.origin.y) / r.dir.y);
}

// Each pixel's red value and whether the checker over [-2, 2]^2 is open where its centre ray
// meets y = 0 (pixels within 0.01 cells of an edge left out); at least 300 of each kind.
void expect_checker_pixels(const Scene& scene, const Image& img, float open_value, float closed_value,
                           float tolerance) {
  int open = 0, closed = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const Vec3 p = pixel_on_plane(scene, x, y, 0.0f);
      float edge;
      const bool is_open = checker_open((p.x + 2.0f) / 4.0f, (p.z + 2.0f) / 4.0f, edge);
      if (edge < 0.01f) continue;
      EXPECT_NEAR(img.rgb[3 * (size_t(y) * img.width + x)], is_open ? open_value : closed_value, tolerance)
          << "pixel " << x << ", " << y;
      (is_open ? open : closed) += 1;
    }
  EXPECT_GT(open, 300);
  EXPECT_GT(closed, 300);
}

Scene load_in(const std::filesystem::path& dir, const std::string& json, const RenderOverrides& ov = {}) {
  return load_scene_text(json, (dir / "s.json").string(), ov);
}

// The screen at y = 1 over [-2, 2]^2, its quad coordinates (x + 2) / 4 and (z + 2) / 4, masked
// by the checker; a sun of irradiance 2 straight down; the floor of albedo 0.5 at y = 0, seen
// from between the two, so only the floor is in view: lit 0.5 * 2 / pi under an open cell.
TEST(Alpha, AMaskedScreenCastsTheShadowOfItsClosedCellsExactly) {
  const auto dir = test::temp_dir("alpha-screen");
  write_checker_mask(dir);
  const Scene scene = load_in(dir, R"({"format": "tracer-scene/1",
    "camera": {"from": [0.3, 0.6, 0.2], "to": [0.3, 0, 0.2001], "up": [0, 0, -1], "vfov": 90},
    "film": {"width": 48, "height": 48}, "render": {"integrator": "path", "spp": 1, "sampler": "center", "max_depth": 3},
    "materials": {"floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]},
      "screen": {"type": "lambert", "albedo": [0, 0, 0], "alpha_mode": "mask", "alpha_map": "mask.png"}},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [2, 2, 2]}],
    "shapes": [{"type": "quad", "corner": [-4, 0, -4], "u": [0, 0, 8], "v": [8, 0, 0], "material": "floor"},
      {"type": "quad", "corner": [-2, 1, -2], "u": [4, 0, 0], "v": [0, 0, 4], "material": "screen"}]})");
  std::filesystem::remove_all(dir);
  RenderStats stats;
  const Image img = render_cpu(scene, 1, stats);
  expect_checker_pixels(scene, img, float(0.5 * 2.0 / M_PI), 0.0f, 1e-6f);
}

// Seen from above, a black masked quad over nothing shows the background (radiance 1) exactly
// where it is open.
TEST(Alpha, CameraRaysSeeTheBackgroundExactlyWhereAMaskedQuadIsOpen) {
  const auto dir = test::temp_dir("alpha-camera");
  write_checker_mask(dir);
  const Scene scene = load_in(dir, R"({"format": "tracer-scene/1",
    "camera": {"from": [0.1, 3, -0.2], "to": [0.1, 0, -0.1999], "up": [0, 0, -1], "vfov": 50},
    "film": {"width": 40, "height": 40}, "render": {"integrator": "whitted", "spp": 1, "sampler": "center"},
    "background": {"type": "constant", "radiance": [1, 1, 1]},
    "materials": {"screen": {"type": "lambert", "albedo": [0, 0, 0], "alpha_mode": "mask", "alpha_map": "mask.png"}},
    "shapes": [{"type": "quad", "corner": [-2, 0, -2], "u": [4, 0, 0], "v": [0, 0, 4], "material": "screen"}]})");
  std::filesystem::remove_all(dir);
  RenderStats stats;
  const Image img = render_cpu(scene, 1, stats);
  expect_checker_pixels(scene, img, 1.0f, 0.0f, 0.0f);
}

// A blended screen of alpha a: the floor receives (1 - a) of the sun in expectation; every path
// draws its own keep-or-pass, so the pixels are independent.
Image under_blended_screen(double alpha) {
  RenderStats stats;
  return render_cpu(test::scene_from(R"({"format": "tracer-scene/1",
    "camera": {"from": [0.3, 0.6, 0.2], "to": [0.3, 0, 0.2001], "up": [0, 0, -1], "vfov": 90},
    "film": {"width": 32, "height": 32}, "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 3},
    "materials": {"floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]},
      "screen": {"type": "lambert", "albedo": [0, 0, 0], "alpha_mode": "blend", "alpha": )" +
                                     std::to_string(alpha) + R"(}},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [2, 2, 2]}],
    "shapes": [{"type": "quad", "corner": [-4, 0, -4], "u": [0, 0, 8], "v": [8, 0, 0], "material": "floor"},
      {"type": "quad", "corner": [-2, 1, -2], "u": [4, 0, 0], "v": [0, 0, 4], "material": "screen"}]})"),
                    0, stats);
}

TEST(Alpha, ABlendedScreenPassesOneMinusAlphaOfTheLight) {
  const float lit = float(0.5 * 2.0 / M_PI);
  const test::MeanStat m = test::channel_mean(under_blended_screen(0.3), 0);
  EXPECT_NEAR(m.mean, 0.7 * lit, 5 * m.stderr_) << "standard error " << m.stderr_;
  EXPECT_GT(m.stderr_, 0.0);
  for (float v : under_blended_screen(0.0).rgb) ASSERT_NEAR(v, lit, 1e-6f);
  for (float v : under_blended_screen(1.0).rgb) ASSERT_EQ(v, 0.0f);
}

// Masked and blended spheres, quads, a plane and mesh triangles with uvs: every structure keeps
// the same hits with either triangle test, so the image is the same bit for bit.
TEST(Alpha, EveryStructureKeepsTheSameHits) {
  const auto dir = test::temp_dir("alpha-structures");
  write_checker_mask(dir);
  for (const char* triangle_test : {"watertight", "moller-trumbore"}) {
    SCOPED_TRACE(triangle_test);
    std::string json = R"({"format": "tracer-scene/1",
    "camera": {"from": [0.4, 1.2, 3.5], "to": [0, 0.5, 0], "vfov": 50},
    "film": {"width": 40, "height": 30}, "render": {"integrator": "path", "spp": 4, "sampler": "sobol", "max_depth": 4,
      "triangle_test": "TRIANGLE_TEST"},
    "background": {"type": "gradient", "zenith": [0.2, 0.3, 0.6], "horizon": [0.6, 0.6, 0.6]},
    "materials": {"floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5], "alpha_mode": "mask", "alpha_map": "mask.png", "alpha_cutoff": 0.3},
      "card": {"type": "lambert", "albedo": [0.2, 0.6, 0.2], "alpha_mode": "mask", "alpha_map": "mask.png"},
      "ghost": {"type": "lambert", "albedo": [0.8, 0.3, 0.2], "alpha_mode": "blend", "alpha": 0.5, "alpha_map": "mask.png"}},
    "lights": [{"type": "directional", "direction": [-0.3, -0.8, -0.4], "irradiance": [2, 2, 2]}],
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
      {"type": "quad", "corner": [-1.2, 0, 0], "u": [1, 0, -0.3], "v": [0, 1.1, 0], "material": "card"},
      {"type": "sphere", "center": [0.6, 0.5, 0], "radius": 0.5, "material": "ghost"},
      {"type": "sphere", "center": [-0.4, 0.35, 0.8], "radius": 0.35, "material": "card"},
      {"type": "mesh", "positions": [[0.2, 0.1, 0.9], [1.2, 0.2, 0.6], [0.4, 1.2, 0.5], [1.3, 1.1, 0.2]],
       "uvs": [[0, 0], [1, 0], [0, 1], [1, 1]], "indices": [[0, 1, 2], [2, 1, 3]], "material": "ghost"}]})";
    json.replace(json.find("TRIANGLE_TEST"), std::strlen("TRIANGLE_TEST"), triangle_test);
    RenderOverrides ov;
    ov.accel = AccelKind::None;
    RenderStats stats;
    const Image reference = render_cpu(load_in(dir, json, ov), 1, stats);
    for (const AccelKind accel :
         {AccelKind::Bvh, AccelKind::Lbvh, AccelKind::Kdtree, AccelKind::KdtreeMedian, AccelKind::Grid}) {
      ov.accel = accel;
      const Image img = render_cpu(load_in(dir, json, ov), 1, stats);
      EXPECT_EQ(img.rgb, reference.rgb) << enum_name(accel) << " differs from the brute-force hits";
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(Alpha, KeysThatCannotMeanAnythingAreRefused) {
  const auto dir = test::temp_dir("alpha-keys");
  write_checker_mask(dir);
  const auto scene = [](const std::string& material) {
    return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 4, "height": 4}, "materials": {"m": )" +
           material + R"(}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
  };
  test::expect_load_error(dir, scene(R"({"type": "lambert", "albedo": [1, 1, 1], "alpha": 0.5})"), "materials.m.alpha");
  test::expect_load_error(dir, scene(R"({"type": "lambert", "albedo": [1, 1, 1], "alpha_mode": "cutout"})"),
                          "alpha_mode");
  test::expect_load_error(dir, scene(R"({"type": "lambert", "albedo": [1, 1, 1], "alpha_mode": "mask", "alpha": 2})"),
                          "materials.m.alpha");
  test::expect_load_error(
      dir, scene(R"({"type": "lambert", "albedo": [1, 1, 1], "alpha_mode": "mask", "alpha_map": "none.png"})"),
      "does not exist");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
