// The equirectangular environment map (kernel/light/equirect_map.h) against answers from outside
// the renderer: its orientation read back from a map of coordinates, chi-square tests of its
// sampler on a one-hot map, a constant map and a real sky (CC0, scenes/textures/sunrise.exr),
// the density integrating to 1 and E[1 / pdf] to 4 pi, a constant map's density 1 / 4 pi at the
// poles too, a one-hot map's sample weights bounded by its cells' power, and no seam where the
// longitude wraps. Significance and sample count as in test_sampling_chi2.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <vector>

#include "chi2.h"
#include "image/image_io.h"
#include "kernel/light/light.h"
#include "test_util.h"

namespace tracer {
namespace {

constexpr int kSamples = 400000;
constexpr double kSignificance = 1e-3;

// A path-traced scene of nothing but an environment map, `map` relative to dir or absolute.
Scene map_only_scene(const std::filesystem::path& dir, const std::string& map, double rotation = 0) {
  return load_scene_text(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 4, "height": 4}, "render": {"integrator": "path"},
      "background": {"type": "environment", "file": ")" +
                             map + R"(", "rotation": )" + std::to_string(rotation) +
                             R"(}, "materials": {}, "shapes": []})",
                         (dir / "s.json").string());
}

// Writes a w x h map into dir/map.exr, texel (x, y) of colour texel(x, y), and loads it.
Scene written_map_scene(const std::string& name, uint32_t w, uint32_t h,
                        const std::function<Vec3(uint32_t, uint32_t)>& texel, double rotation = 0) {
  const auto dir = test::temp_dir(name);
  write_image(test::image_from(w, h, texel), (dir / "map.exr").string());
  Scene scene = map_only_scene(dir, "map.exr", rotation);
  std::filesystem::remove_all(dir);
  return scene;
}

// The map-frame direction at (u, t): the inverse of equirect_coordinates.
Vec3 map_direction(double u, double t) {
  const double theta = M_PI * t, phi = 2 * M_PI * u;
  return Vec3{float(-std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(-std::sin(theta) * std::sin(phi))};
}

void expect_reads(const SceneView& view, Vec3 dir, Vec3 texel) {
  const Vec3 r = background_radiance(view, dir);
  EXPECT_NEAR(r.x, texel.x, 1e-4f) << dir.x << ", " << dir.y << ", " << dir.z;
  EXPECT_NEAR(r.y, texel.y, 1e-4f) << dir.x << ", " << dir.y << ", " << dir.z;
  EXPECT_EQ(r.z, texel.z);
}

// Texel (x, y) holds (x, y, 1): the filtered map returns where it was read.
TEST(EnvironmentMap, LooksAlongPlusXAtItsCentreAndStraightUpAtItsTopRow) {
  const auto coordinates = [](uint32_t x, uint32_t y) { return Vec3{float(x), float(y), 1.0f}; };
  const Scene scene = written_map_scene("env-orient", 8, 4, coordinates);
  const SceneView view = scene.view();
  // u = 0.5 + atan2(z, x) / 2 pi, texel x = 8 u - 0.5; the equator t = 0.5, texel y = 4 t - 0.5.
  expect_reads(view, {1, 0, 0}, {3.5f, 1.5f, 1.0f});
  expect_reads(view, {0, 0, 1}, {5.5f, 1.5f, 1.0f});
  expect_reads(view, {0, 0, -1}, {1.5f, 1.5f, 1.0f});
  EXPECT_EQ(background_radiance(view, {0, 1, 0}).y, 0.0f) << "straight up reads the top row";
  EXPECT_EQ(background_radiance(view, {0, -1, 0}).y, 3.0f) << "straight down reads the bottom row";
  // Turned 90 degrees about +y (counterclockwise seen from above), +x's texels face -z.
  const Scene turned = written_map_scene("env-orient-turned", 8, 4, coordinates, 90);
  expect_reads(turned.view(), {0, 0, -1}, {3.5f, 1.5f, 1.0f});
  expect_reads(turned.view(), {1, 0, 0}, {5.5f, 1.5f, 1.0f});
}

// Directions binned by (u, t) bins, bins_u x bins_t, against the density integrated over
// each bin (midpoint rule in (u, t), dw = 2 pi^2 sin(pi t) du dt); that integral over the
// sphere is 1, and E[1 / pdf] is the solid angle where the density is positive (4 pi but
// for a map dark in places), within its standard error and the density's float rounding.
void expect_sampler_follows_its_density(const SceneView& view, int bins_u, int bins_t) {
  ASSERT_NE(view.environment_light, kNoHit);
  std::vector<double> observed(size_t(bins_u) * bins_t, 0.0), expected(observed.size(), 0.0);
  test::InputStream s{23};
  double inverse_pdf = 0, inverse_pdf2 = 0;
  for (int i = 0; i < kSamples; ++i) {
    const LightSample ls = test::draw_environment(view, s);
    ASSERT_TRUE(ls.valid);
    ASSERT_NEAR(length(ls.wi), 1.0f, 1e-6f);
    float u, t;
    equirect_coordinates(into_map_frame(view.background, ls.wi), u, t);
    const int bu = std::min(bins_u - 1, int(u * bins_u)), bt = std::min(bins_t - 1, int(t * bins_t));
    observed[size_t(bt) * bins_u + bu] += 1;
    inverse_pdf += 1.0 / ls.pdf, inverse_pdf2 += 1.0 / (double(ls.pdf) * ls.pdf);
  }
  constexpr int kQuad = 8;
  double total = 0, support = 0;
  for (int bt = 0; bt < bins_t; ++bt)
    for (int bu = 0; bu < bins_u; ++bu) {
      double p = 0;
      for (int j = 0; j < kQuad; ++j)
        for (int i = 0; i < kQuad; ++i) {
          const double u = (bu + (i + 0.5) / kQuad) / bins_u, t = (bt + (j + 0.5) / kQuad) / bins_t;
          const Vec3 d = out_of_map_frame(view.background, map_direction(u, t));
          const double dw = 2 * M_PI * M_PI * std::sin(M_PI * t) / (double(bins_u) * bins_t * kQuad * kQuad);
          const double pdf = environment_direction_pdf(view, d);
          p += pdf * dw;
          support += pdf > 0 ? dw : 0;
        }
      expected[size_t(bt) * bins_u + bu] = kSamples * p;
      total += p;
    }
  EXPECT_NEAR(total, 1.0, 2e-3) << "the density integrates to 1 over the sphere";
  EXPECT_GT(test::chi2_p_value(observed, expected), kSignificance);
  const double mean = inverse_pdf / kSamples, se = std::sqrt((inverse_pdf2 / kSamples - mean * mean) / kSamples);
  EXPECT_NEAR(mean, support, 5 * se + 1e-3 * support) << "standard error " << se;
}

TEST(SamplingChi2, EnvironmentMapWithLevelsAndABrightTexel) {
  const Scene scene = written_map_scene("env-chi2-levels", 16, 8, [](uint32_t x, uint32_t y) {
    const float level = x == 5 && y == 2 ? 60.0f : 0.1f + 0.05f * float(x % 5) + 0.1f * float(y);
    return Vec3{level, level, level};
  });
  expect_sampler_follows_its_density(scene.view(), 32, 16);
}

TEST(SamplingChi2, EnvironmentMapOneHot) {
  const Scene scene = written_map_scene("env-chi2-one-hot", 16, 8, [](uint32_t x, uint32_t y) {
    return x == 11 && y == 6 ? Vec3{50, 50, 50} : Vec3{0, 0, 0};
  });
  expect_sampler_follows_its_density(scene.view(), 32, 16);
}

TEST(SamplingChi2, EnvironmentMapConstantTurned) {
  const Scene scene = written_map_scene(
      "env-chi2-constant", 16, 8,
      [](uint32_t, uint32_t) {
        return Vec3{0.7f, 0.7f, 0.7f};
      },
      37);
  expect_sampler_follows_its_density(scene.view(), 32, 16);
}

// A real sky: 256 x 128 cells, binned 64 x 32 (four cells a bin each way).
TEST(SamplingChi2, EnvironmentMapOfARealSky) {
  const Scene scene =
      map_only_scene(std::filesystem::temp_directory_path(), test::source_path("scenes/textures/sunrise.exr"));
  ASSERT_EQ(scene.sky_cell_columns, 256u);
  ASSERT_EQ(scene.sky_cell_rows, 128u);
  expect_sampler_follows_its_density(scene.view(), 64, 32);
}

// A constant map is sampled uniformly over the sphere, density 1 / 4 pi, at the poles too
// (within the 2^-24 steps of the cells' probabilities: 2 % of the smallest cell's).
TEST(EnvironmentMap, ConstantMapDensityIsUniformUpToThePoles) {
  const Scene scene = written_map_scene("env-uniform", 64, 32, [](uint32_t, uint32_t) { return Vec3{1, 1, 1}; });
  const SceneView view = scene.view();
  test::InputStream s{5};
  std::vector<Vec3> directions = {{0, 1, 0}, {0, -1, 0}, {1e-4f, 1, 0}, {0, -1, 1e-4f}, {-1, 0, 0}, {-1, 0, -1e-6f}};
  for (int i = 0; i < 2000; ++i) {
    const float cos_theta = 1.0f - 2.0f * s.next();
    directions.push_back(direction_from(cos_theta, s.next()));
  }
  for (const Vec3& d : directions)
    EXPECT_NEAR(environment_direction_pdf(view, normalize(d)) * 4 * M_PI, 1.0, 0.02)
        << d.x << ", " << d.y << ", " << d.z;
}

// One bright texel H: the sampled weight L / pdf = L * (cells' total) / (cell's largest L) is at
// most the total, H times the solid angle of the 3 x 3 cells its filter reaches, and its mean
// is the filtered map's integral (midpoint rule, fine enough to hold it to 0.1 %).
TEST(EnvironmentMap, OneHotMapWeightsAreBoundedAndUnbiased) {
  constexpr uint32_t kW = 64, kH = 32, kX = 20, kY = 9;
  constexpr float kHot = 1000.0f;
  const Scene scene = written_map_scene("env-one-hot", kW, kH, [](uint32_t x, uint32_t y) {
    return x == kX && y == kY ? Vec3{kHot, kHot, kHot} : Vec3{0, 0, 0};
  });
  const SceneView view = scene.view();
  const double block = 3 * (2 * M_PI / kW) * (std::cos(M_PI * (kY - 1) / kH) - std::cos(M_PI * (kY + 2) / kH));
  test::InputStream s{9};
  double sum = 0, sum2 = 0;
  for (int i = 0; i < kSamples; ++i) {
    const LightSample ls = test::draw_environment(view, s);
    ASSERT_TRUE(ls.valid);
    const double w = ls.radiance.x / ls.pdf;
    ASSERT_LE(w, kHot * block * 1.001) << "sample " << i;
    sum += w, sum2 += w * w;
  }
  double integral = 0;
  constexpr int kN = 16;  // points per texel each way
  for (uint32_t j = 0; j < kH * kN; ++j)
    for (uint32_t i = 0; i < kW * kN; ++i) {
      const double u = (i + 0.5) / (kW * kN), t = (j + 0.5) / (kH * kN);
      integral += background_radiance(view, map_direction(u, t)).x * 2 * M_PI * M_PI * std::sin(M_PI * t) /
                  (double(kW) * kN * kH * kN);
    }
  const double mean = sum / kSamples, se = std::sqrt((sum2 / kSamples - mean * mean) / kSamples);
  EXPECT_NEAR(mean, integral, 5 * se + 1e-3 * integral) << "standard error " << se;
}

// Across the seam where u wraps (straight along -x) the filter reads both edges' columns.
TEST(EnvironmentMap, NoSeamWhereTheLongitudeWraps) {
  const Scene scene = written_map_scene("env-seam", 16, 8, [](uint32_t x, uint32_t y) {
    return Vec3{float((x * 7 + y * 3) % 11), float(x), 1.0f};
  });
  const SceneView view = scene.view();
  for (float y : {-0.6f, 0.0f, 0.3f}) {
    const Vec3 a = background_radiance(view, normalize(Vec3{-1, y, 1e-5f}));
    const Vec3 b = background_radiance(view, normalize(Vec3{-1, y, -1e-5f}));
    EXPECT_NEAR(a.x, b.x, 1e-3f) << "at height " << y;
    EXPECT_NEAR(a.y, b.y, 1e-3f) << "at height " << y;
    EXPECT_NEAR(a.y, 7.5f, 1e-3f) << "halfway between the last column and the first";
  }
}

}  // namespace
}  // namespace tracer
