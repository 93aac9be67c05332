// The path tracer lit by an equirectangular environment map against closed forms and an
// invariance: a white furnace (a convex Lambert object under a constant map renders its albedo
// times the map), an up-facing Lambert plane under radiance a + b cos(theta) (irradiance
// E = pi (a + 2b/3)), each with the map sampled as a light and without; a scene turned a quarter
// turn about +y with its map renders the same; and the map's scene keys and --environment
// refusing bad values with exit 2. Tolerances as in test_path_analytic.cpp: five standard
// errors of the pixel mean.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

using test::MeanStat;

// Renders `json` as dir/s.json beside map.exr, w x h texels coloured texel(x, y).
Image render_under_map(const std::string& name, uint32_t w, uint32_t h,
                       const std::function<Vec3(uint32_t, uint32_t)>& texel, const std::string& json,
                       bool sky_sampling) {
  const auto dir = test::temp_dir(name);
  write_image(test::image_from(w, h, texel), (dir / "map.exr").string());
  RenderOverrides ov;
  ov.sky_sampling = sky_sampling ? Switch::On : Switch::Off;
  RenderStats stats;
  Image img = render_cpu(load_scene_text(json, (dir / "s.json").string(), ov), 0, stats);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  return img;
}

// A Lambert sphere of albedo 0.6 filling the view (its angular radius 14.5 degrees, the view's
// half-angle 5) under a constant map of radiance 1: every pixel's expectation is 0.6, and with
// BSDF rays alone every path's value is (the cosine-weighted direction cancels the cosine).
void furnace(bool sky_sampling) {
  const Image img = render_under_map(
      "env-furnace", 16, 8,
      [](uint32_t, uint32_t) {
        return Vec3{1, 1, 1};
      },
      R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": [0, 0, 0], "vfov": 10},
    "film": {"width": 24, "height": 24}, "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 4},
    "background": {"type": "environment", "file": "map.exr", "rotation": 25},
    "materials": {"m": {"type": "lambert", "albedo": [0.6, 0.6, 0.6]}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})",
      sky_sampling);
  const MeanStat m = test::channel_mean(img, 1);
  EXPECT_NEAR(m.mean, 0.6, 5 * m.stderr_ + 1e-6) << "stderr " << m.stderr_;
  if (sky_sampling) {
    EXPECT_GT(m.stderr_, 0.0) << "the estimator has variance here";
  } else {
    for (float v : img.rgb) ASSERT_NEAR(v, 0.6f, 1e-6f);
  }
}

TEST(EnvironmentLight, FurnaceWithTheMapSampled) { furnace(true); }
TEST(EnvironmentLight, FurnaceWithBsdfRaysAlone) { furnace(false); }

// L(theta) = a + b max(cos theta, 0), a = 0.5, b = 1.5, on 128 rows: the plane of albedo 0.5
// reflects 0.5 E / pi = 0.5 (a + 2b / 3) = 0.75. The filter interpolates cos linearly between
// row centres, off by at most b (pi / 128)^2 / 8 = 1.1e-4, a tenth of the tolerance.
void plane_under_cosine_sky(bool sky_sampling) {
  const Image img = render_under_map(
      "env-cosine", 8, 128,
      [](uint32_t, uint32_t y) {
        const float c = float(std::max(0.0, std::cos(M_PI * (y + 0.5) / 128)));
        const float level = 0.5f + 1.5f * c;
        return Vec3{level, level, level};
      },
      R"({"format": "tracer-scene/1", "camera": {"from": [0, 2, 0], "to": [0, 0, 0.01], "vfov": 60},
    "film": {"width": 32, "height": 32}, "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 4},
    "background": {"type": "environment", "file": "map.exr", "rotation": -70},
    "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})",
      sky_sampling);
  const MeanStat m = test::channel_mean(img, 0);
  EXPECT_NEAR(m.mean, 0.75, 5 * m.stderr_) << "stderr " << m.stderr_;
  EXPECT_GT(m.stderr_, 0.0);
}

TEST(EnvironmentLight, PlaneUnderACosineSkyWithTheMapSampled) { plane_under_cosine_sky(true); }
TEST(EnvironmentLight, PlaneUnderACosineSkyWithBsdfRaysAlone) { plane_under_cosine_sky(false); }

// A sphere and a floor under the real sky, and the same scene turned a quarter turn about +y,
// (x, y, z) -> (z, y, -x), with the map turned 90 degrees more: the same image in expectation
// (not path by path: a surface's sampling frame does not turn with the scene). Each quadrant's
// mean of the pixel-by-pixel difference is zero within five standard errors of that mean.
std::string turned_scene(bool turned) {
  const auto p = [&](double x, double y, double z) {
    return "[" + std::to_string(turned ? z : x) + ", " + std::to_string(y) + ", " + std::to_string(turned ? -x : z) +
           "]";
  };
  return R"({"format": "tracer-scene/1", "camera": {"from": )" + p(0.5, 1.2, 3.5) + R"(, "to": )" + p(0, 0.4, 0) +
         R"(, "vfov": 45},
    "film": {"width": 32, "height": 24}, "render": {"integrator": "path", "spp": 64, "sampler": "stochastic", "max_depth": 3},
    "background": {"type": "environment", "file": ")" +
         test::source_path("scenes/textures/sunrise.exr") + R"(", "rotation": )" + (turned ? "130" : "40") + R"(},
    "materials": {"m": {"type": "lambert", "albedo": [0.6, 0.5, 0.4]}, "g": {"type": "conductor", "albedo": [0.9, 0.8, 0.5], "roughness": 0.3}},
    "shapes": [{"type": "sphere", "center": )" +
         p(-0.4, 0.4, 0) + R"(, "radius": 0.4, "material": "g"},
      {"type": "quad", "corner": [-2, 0, -2], "u": [0, 0, 4], "v": [4, 0, 0], "material": "m"}]})";
}

TEST(EnvironmentLight, ASceneTurnedWithItsMapRendersTheSame) {
  RenderStats stats;
  const Image a = render_cpu(test::scene_from(turned_scene(false)), 0, stats);
  const Image b = render_cpu(test::scene_from(turned_scene(true)), 0, stats);
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  for (uint32_t quadrant = 0; quadrant < 4; ++quadrant)
    for (int c = 0; c < 3; ++c) {
      double sum = 0, sum2 = 0, n = 0;
      for (uint32_t y = (quadrant / 2) * a.height / 2; y < (quadrant / 2 + 1) * a.height / 2; ++y)
        for (uint32_t x = (quadrant % 2) * a.width / 2; x < (quadrant % 2 + 1) * a.width / 2; ++x) {
          const size_t i = 3 * (size_t(y) * a.width + x) + c;
          const double d = double(a.rgb[i]) - b.rgb[i];
          sum += d, sum2 += d * d, n += 1;
        }
      const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
      EXPECT_NEAR(mean, 0.0, 5 * se) << "quadrant " << quadrant << " channel " << c << ", standard error " << se;
    }
}

TEST(EnvironmentLight, BadKeysAreRefusedNamingThem) {
  const auto dir = test::temp_dir("env-keys");
  write_image(test::image_from(4, 2, [](uint32_t, uint32_t) { return Vec3{1, 1, 1}; }), (dir / "map.exr").string());
  const auto scene = [](const std::string& background) {
    return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 4, "height": 4}, "background": )" +
           background + R"(, "materials": {}, "shapes": []})";
  };
  test::expect_load_error(dir, scene(R"({"type": "environment", "file": "map.exr", "strength": -1})"),
                          "background.strength");
  test::expect_load_error(dir, scene(R"({"type": "environment", "file": "map.exr", "rotation": 1e7})"),
                          "background.rotation");
  test::expect_load_error(dir, scene(R"({"type": "environment", "file": "none.exr"})"), "does not exist");
  test::expect_load_error(dir, scene(R"({"type": "environment"})"), "file");
  test::expect_load_error(dir, scene(R"({"type": "environment", "file": "map.exr", "faces": []})"), "faces");
  std::filesystem::remove_all(dir);
}

TEST(EnvironmentLight, CommandLineEnvironmentLightsAGltfFileAndRefusesAMissingOne) {
  const auto dir = test::temp_dir("env-cli");
  const std::string model = test::source_path("scenes/gltf/cornell-box.gltf");
  std::string out;
  EXPECT_EQ(test::run_tracer(
                "render " + model + " --environment " + (dir / "none.exr").string() + " -o " + (dir / "a.png").string(),
                &out),
            2);
  EXPECT_NE(out.find("--environment"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  EXPECT_EQ(test::run_tracer(
                "render " + model + " --environment x.exr --background 1,1,1 -o " + (dir / "b.png").string(), &out),
            2);
  EXPECT_NE(out.find("--background and --environment"), std::string::npos) << out;
  EXPECT_EQ(
      test::run_tracer("info " + model + " --environment " + test::source_path("scenes/textures/sunrise.exr"), &out), 0)
      << out;
  EXPECT_NE(out.find("background environment (256x128 texels), a light of 256x128 cells"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
