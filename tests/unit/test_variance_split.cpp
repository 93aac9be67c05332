// The path split of `tracer bench variance` (bench/variance_split.h): its classes add up to
// the integrator's own sample bit for bit (the Cornell box: at most one term per vertex), and
// each class holds only what its definition allows: light seen directly under an empty sky is
// the escape class at 0 vertices with the sky's radiance exactly; max_depth 1 leaves nothing
// past one vertex; nee off leaves no light sample; mirror images only with a flat mirror.
#include <gtest/gtest.h>

#include "bench/variance_split.h"
#include "kernel/integrator/render_pixel.h"
#include "test_util.h"

namespace tracer {
namespace {

Scene box(const RenderOverrides& extra = {}) {
  RenderOverrides ov = extra;
  ov.width = 24;
  ov.height = 18;
  return load_scene(test::source_path("scenes/cornell-box-path.json"), ov);
}

TEST(VarianceSplit, TheClassesAddUpToTheSampleBitForBit) {
  const Scene scene = box();
  const SceneView view = scene.view();
  uint64_t terms = 0;
  for (uint32_t y = 0; y < view.settings.height; ++y)
    for (uint32_t x = 0; x < view.settings.width; ++x)
      for (uint32_t s = 0; s < 4; ++s) {
        RayCounts counts{};
        const Vec3 expected = render_sample_as<IntegratorKind::Path>(view, x, y, s, counts);
        Vec3 sum = {0, 0, 0};
        const Vec3 total = split_path_sample(view, x, y, s, [&](uint32_t c, Vec3 r) {
          EXPECT_LT(c, kPathClasses);
          sum += r;
          ++terms;
        });
        ASSERT_EQ(total, expected) << x << ", " << y << " sample " << s;
        EXPECT_EQ(sum, expected);
      }
  EXPECT_GT(terms, 24u * 18u);
}

TEST(VarianceSplit, AnEmptySceneIsTheEscapeClassAtZeroVertices) {
  const Scene scene = test::scene_from(R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 0, 0], "to": [0, 0, -1], "vfov": 40}, "film": {"width": 4, "height": 3},
    "render": {"integrator": "path", "spp": 2}, "background": {"type": "constant", "radiance": [0.25, 0.5, 2]},
    "materials": {}, "shapes": []})");
  const SplitImages split = render_split(scene.view(), 0, 2, 1, {});
  const VertexLobe none[2] = {VertexLobe::Diffuse, VertexLobe::Diffuse};
  const uint32_t escape = path_class(PathEstimator::Escape, 0, none);
  for (uint32_t c = 0; c < kPathClasses; ++c) EXPECT_EQ(split.sums[c] != nullptr, c == escape) << path_class_name(c);
  const std::vector<double>& sky = *split.sums[escape];
  for (size_t i = 0; i < sky.size(); i += 3) {
    EXPECT_EQ(sky[i], 0.5);
    EXPECT_EQ(sky[i + 1], 1.0);
    EXPECT_EQ(sky[i + 2], 4.0);
  }
}

TEST(VarianceSplit, EachClassHoldsOnlyWhatItsDefinitionAllows) {
  RenderOverrides one_bounce;
  one_bounce.max_depth = 1;
  const SplitImages shallow = render_split(box(one_bounce).view(), 0, 4, 0, {});
  RenderOverrides plain;
  plain.nee = Switch::Off;
  const SplitImages no_nee = render_split(box(plain).view(), 0, 4, 0, {});
  const SplitImages full = render_split(box().view(), 0, 4, 0, {});
  bool deep = false, sampled = false;
  for (uint32_t c = 0; c < kPathClasses; ++c) {
    const PathEstimator e = path_class_estimator(c);
    if (shallow.sums[c]) {
      EXPECT_LE(path_class_vertices(c), 1u) << path_class_name(c);
    }
    if (no_nee.sums[c]) {
      EXPECT_NE(e, PathEstimator::LightSample) << path_class_name(c);
    }
    EXPECT_FALSE(full.sums[c] && e == PathEstimator::MirrorImage) << "no flat mirror in the box";
    deep |= full.sums[c] && path_class_vertices(c) >= 2;
    sampled |= full.sums[c] && e == PathEstimator::LightSample;
  }
  EXPECT_TRUE(deep);
  EXPECT_TRUE(sampled);
  const SplitImages mirrors = render_split(load_scene(test::source_path("scenes/cornell-box-mirror-box.json"),
                                                      [] {
                                                        RenderOverrides ov;
                                                        ov.width = 24, ov.height = 18;
                                                        return ov;
                                                      }())
                                               .view(),
                                           0, 4, 0, {});
  bool imaged = false;
  for (uint32_t c = 0; c < kPathClasses; ++c)
    imaged |= mirrors.sums[c] && path_class_estimator(c) == PathEstimator::MirrorImage;
  EXPECT_TRUE(imaged) << "the mirror box's light seen in its flat mirrors";
}

TEST(VarianceSplit, ClassNamesSayWhatTheyHold) {
  const VertexLobe ds[2] = {VertexLobe::Diffuse, VertexLobe::Specular};
  EXPECT_EQ(path_class_name(path_class(PathEstimator::LightSample, 2, ds)),
            "light sample, 2 vertices, diffuse > specular");
  EXPECT_EQ(path_class_name(path_class(PathEstimator::Emission, 7, ds)),
            "emission hit, 4+ vertices, diffuse > specular");
  EXPECT_EQ(path_class_name(path_class(PathEstimator::Escape, 1, ds)), "escape, 1 vertices, specular");
  EXPECT_EQ(path_class_name(path_class(PathEstimator::MirrorImage, 0, ds)), "mirror image, 0 vertices");
}

// What the command refuses, exit 2 naming the key: a Whitted scene (nothing to split), a
// reference of no more samples than the measurement.
TEST(VarianceSplit, TheCommandRefusesWhatItCannotSplit) {
  std::string out;
  EXPECT_EQ(
      test::run_tracer("bench variance " + test::source_path("scenes/cornell-box.json") + " --spp 1 --ref-spp 2", &out),
      2);
  EXPECT_NE(out.find("cornell-box.json: render.integrator: bench variance splits the path integrator"),
            std::string::npos)
      << out;
  EXPECT_EQ(test::run_tracer("bench variance " + test::source_path("scenes/cornell-box-path.json") +
                                 " --spp 16 --ref-spp 16 --width 4 --height 3",
                             &out),
            2);
  EXPECT_NE(out.find("--ref-spp 16: must exceed --spp"), std::string::npos) << out;
}

}  // namespace
}  // namespace tracer
