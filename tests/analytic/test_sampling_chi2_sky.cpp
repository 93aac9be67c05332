// Chi-square goodness-of-fit tests of the cube-map sky's sampling (the path integrator's
// environment light): directions binned by cells of the faces against environment_direction_pdf
// integrated over each bin, E[1 / pdf] against the whole sphere, and a lone bright texel
// that must still give its cell a probability. Significance and sample count as in
// test_sampling_chi2.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "chi2.h"
#include "kernel/light/light.h"
#include "test_util.h"

namespace tracer {
namespace {

constexpr int kSamples = 400000;
constexpr double kSignificance = 1e-3;

// A path-traced scene of nothing but the cube-map sky whose faces were written into dir.
Scene sky_only_scene(const std::filesystem::path& dir, const std::string& faces) {
  return load_scene_text(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 4, "height": 4}, "render": {"integrator": "path"},
      "background": {"type": "cubemap", "faces": [)" +
                             faces + R"(]}, "materials": {}, "shapes": []})",
                         (dir / "s.json").string());
}

// A cube-map sky with a different level on each face and one bright texel: directions are
// binned by quarter cells of the faces (2 x 2 per cell), each bin expecting the integral of
// environment_direction_pdf over it (midpoint rule in face coordinates, dw = dA / r^3); E[1 / pdf]
// is the whole sphere, 4 pi.
TEST(SamplingChi2, CubeMapSkyCellsByTheirDensity) {
  const auto dir = test::temp_dir("sky-chi2");
  constexpr int kSize = 4, kBinsPerSide = 2 * kSize;
  const std::string faces = test::write_cube_faces(dir, kSize, [](int face, int x, int y) {
    const float level = face == 2 && x == 1 && y == 2 ? 40.0f : 0.2f + 0.2f * face;
    return Vec3{level, level, level};
  });
  const Scene scene = sky_only_scene(dir, faces);
  std::filesystem::remove_all(dir);
  const SceneView view = scene.view();
  ASSERT_EQ(view.environment_light, 0u);
  ASSERT_EQ(view.sky_cell_columns, uint32_t(kSize));
  std::vector<double> observed(6 * kBinsPerSide * kBinsPerSide, 0.0), expected(observed.size(), 0.0);
  test::InputStream s{17};
  double inverse_pdf = 0, inverse_pdf2 = 0;
  for (int i = 0; i < kSamples; ++i) {
    const LightSample ls = test::draw_environment(view, s);
    ASSERT_TRUE(ls.valid);
    ASSERT_NEAR(length(ls.wi), 1.0f, 1e-6f);
    float u, v;
    const uint32_t face = cube_face(ls.wi, u, v);
    const int bx = std::min(kBinsPerSide - 1, int(u * kBinsPerSide)),
              by = std::min(kBinsPerSide - 1, int(v * kBinsPerSide));
    observed[(face * kBinsPerSide + by) * kBinsPerSide + bx] += 1;
    inverse_pdf += 1.0 / ls.pdf, inverse_pdf2 += 1.0 / (double(ls.pdf) * ls.pdf);
  }
  constexpr int kQuad = 8;  // midpoint-rule points per bin side
  for (uint32_t face = 0; face < 6; ++face)
    for (int by = 0; by < kBinsPerSide; ++by)
      for (int bx = 0; bx < kBinsPerSide; ++bx) {
        double p = 0;
        for (int j = 0; j < kQuad; ++j)
          for (int i = 0; i < kQuad; ++i) {
            const double a = -1 + 2 * (bx + (i + 0.5) / kQuad) / kBinsPerSide,
                         b = -1 + 2 * (by + (j + 0.5) / kQuad) / kBinsPerSide;
            const double r2 = 1 + a * a + b * b, area = 4.0 / (kBinsPerSide * kBinsPerSide * kQuad * kQuad);
            p += environment_direction_pdf(view, normalize(cube_direction(face, float(a), float(b)))) * area /
                 (r2 * std::sqrt(r2));
          }
        expected[(face * kBinsPerSide + by) * kBinsPerSide + bx] = kSamples * p;
      }
  EXPECT_GT(test::chi2_p_value(observed, expected), kSignificance);
  const double mean = inverse_pdf / kSamples, se = std::sqrt((inverse_pdf2 / kSamples - mean * mean) / kSamples);
  EXPECT_NEAR(mean, 4 * M_PI, 5 * se) << "standard error " << se;
}

// Faces of 384 texels give cells of 3 x 3 texels: a lone bright texel on a cell's edge, off
// its centre and corners, still gives its cell a probability (the cell's weight is the
// filtered sky's largest value over the cell, not a few points of it).
TEST(SamplingChi2, CubeMapSkyCellSeesALoneTexelOffItsCentre) {
  const auto dir = test::temp_dir("sky-lone-texel");
  constexpr int kSize = 384;
  const std::string faces = test::write_cube_faces(dir, kSize, [](int face, int x, int y) {
    return face == 0 && x == 0 && y == 1 ? Vec3{100, 100, 100} : Vec3{0, 0, 0};
  });
  const Scene scene = sky_only_scene(dir, faces);
  std::filesystem::remove_all(dir);
  const SceneView view = scene.view();
  ASSERT_EQ(view.environment_light, 0u) << "the sky has a sampling distribution";
  ASSERT_EQ(view.sky_cell_columns, 128u);
  const float u = 0.5f / kSize, v = 1.0f - 1.5f / kSize;  // texel (0, 1)'s centre
  EXPECT_GT(environment_direction_pdf(view, normalize(cube_direction(0, 2 * u - 1, 2 * v - 1))), 0.0f);
}

}  // namespace
}  // namespace tracer
