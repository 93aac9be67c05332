// Next-event estimation through a flat mirror (kernel/shading/mirror_images.h) against closed
// forms. A lamp seen in a mirror of reflectance R lights a point x as R times the lamp lights
// the mirror image of x (x reflected across the mirror's plane, with its normal), which
// Lambert's polygon formula gives. The image samples reproduce it, each with the density the
// BSDF side's MIS weight evaluates for the same path; a render of a Lambert floor lit only off
// the mirror reproduces it with the image samples and without them (only BSDF rays find the
// lamp), the former with far less noise; a scene with no planar mirror renders the same image
// bit for bit either way.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "kernel/shading/mirror_images.h"
#include "light_fixture.h"
#include "options/render_options.h"
#include "render/render_cpu.h"
#include "render/stream_states.h"

namespace tracer {
namespace {

using test::MeanEstimate;

// A mirror in the plane x = 0 facing +x, reflectance 0.8; a lamp of radiance 1 at x = 1
// facing the mirror (y from 1.6 to 3.6, z from -1 to 1), whose back is all a point beyond
// x = 1 could see of it directly.
constexpr Vec3 kLampCorner = {1.0f, 1.6f, -1.0f}, kLampU = {0.0f, 0.0f, 2.0f}, kLampV = {0.0f, 2.0f, 0.0f};
constexpr float kReflectance = 0.8f;

const std::string kMirrorQuad =
    R"({"type": "quad", "corner": [0, -1, -5], "u": [0, 10, 0], "v": [0, 0, 10], "material": "mirror"})";
const std::string kMirrorPlane = R"({"type": "plane", "point": [0, 0, 0], "normal": [1, 0, 0], "material": "mirror"})";

std::string mirror_scene(const std::string& light_sampling, const std::string& extra_shapes = "",
                         const std::string& mirror = kMirrorQuad) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [2, 4, 0], "to": [2, 0, 0.01], "vfov": 0.5},
    "film": {"width": 16, "height": 16},
    "render": {"integrator": "path", "spp": 64, "sampler": "stochastic", "max_depth": 2, "mirror_images": true,
               "light_sampling": ")" +
         light_sampling + R"("},
    "materials": {"lamp": {"type": "emissive", "radiance": [1, 1, 1]},
                  "mirror": {"type": "metal", "albedo": [0.8, 0.8, 0.8], "roughness": 0},
                  "floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [)" +
         mirror + R"(,
               {"type": "quad", "corner": )" +
         test::json_array(kLampCorner) + R"(, "u": )" + test::json_array(kLampU) + R"(, "v": )" +
         test::json_array(kLampV) + R"(, "material": "lamp"})" + extra_shapes + "]}";
}

// Irradiance the lamp gives x (normal n) off the mirror: R E(x', n') with x' and n' reflected
// across x = 0.
double irradiance_off_the_mirror(Vec3 x, Vec3 n) {
  const Vec3 image = {-x.x, x.y, x.z}, image_n = {-n.x, n.y, n.z};
  return kReflectance *
         test::polygon_irradiance(
             image, image_n, {kLampCorner, kLampCorner + kLampU, kLampCorner + kLampU + kLampV, kLampCorner + kLampV});
}

void expect_image_samples_give_irradiance(const std::string& light_sampling, const std::string& mirror = kMirrorQuad) {
  const Scene scene = test::scene_from(mirror_scene(light_sampling, "", mirror));
  const SceneView view = scene.view();
  ASSERT_EQ(view.mirror_count, 1u);
  const uint32_t lamp = 1;
  const struct {
    Vec3 x, n;
  } cases[] = {{{2.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},
               {{0.6f, 2.0f, 0.3f}, {-1.0f, 0.0f, 0.0f}},
               {{3.0f, 4.5f, -0.8f}, normalize(Vec3{-1.0f, -0.5f, 0.2f})}};
  for (const auto& c : cases) {
    test::InputStream s{7};
    MeanEstimate irradiance;
    int valid = 0;
    for (int i = 0; i < 200000; ++i) {
      const float pick = s.next(), which = s.next(), u1 = s.next(), u2 = s.next();
      const MirrorImageSample is = sample_mirror_image(view, c.x, pick, which, u1, u2);
      if (!is.valid) {
        irradiance.add(0.0);
        continue;
      }
      ++valid;
      ASSERT_EQ(is.mirror, 0u);
      ASSERT_EQ(is.light, lamp);
      ASSERT_NEAR(dot(is.wi_light, Vec3{1, 0, 0}), -dot(is.wi, Vec3{1, 0, 0}), 1e-6f) << "wi folded across x = 0";
      ASSERT_NEAR(is.mirror_point.x, 0.0f, 1e-5f);
      // The density the BSDF side's MIS weight evaluates for the same path, from where the path
      // meets the lamp.
      float t = 0, alpha = 0, beta = 0;
      ASSERT_TRUE(
          intersect_quad(kLampCorner, kLampU, kLampV, {is.mirror_point, is.wi_light}, 0.0f, kInfinity, t, alpha, beta));
      const float pdf = mirror_image_pdf(view, is.mirror, is.light, c.x, is.wi_light, is.mirror_point + is.wi_light * t,
                                         Vec3{-1.0f, 0.0f, 0.0f});
      ASSERT_NEAR(pdf, is.pdf, 2e-5f * is.pdf);
      irradiance.add(double(is.radiance.x) * std::max(0.0f, dot(c.n, is.wi)) / is.pdf);
    }
    EXPECT_GT(valid, 100000) << "the mirror holds the whole image of the lamp";
    EXPECT_NEAR(irradiance.mean(), irradiance_off_the_mirror(c.x, c.n), irradiance.tolerance())
        << light_sampling << " from " << c.x.x << " " << c.x.y << " " << c.x.z;
  }
}

TEST(MirrorImages, SamplesGiveTheIrradianceOfTheLampsImageWithAreaSampling) {
  expect_image_samples_give_irradiance("area");
}

TEST(MirrorImages, SamplesGiveTheIrradianceOfTheLampsImageWithSolidAngleSampling) {
  expect_image_samples_give_irradiance("solid-angle");
}

TEST(MirrorImages, AnInfinitePlaneMirrorGivesTheSameIrradiance) {
  expect_image_samples_give_irradiance("solid-angle", kMirrorPlane);
}

// Behind the mirror, or with the lamp behind its plane, no image sample is valid.
TEST(MirrorImages, NoSampleFromBehindTheMirror) {
  const Scene scene = test::scene_from(mirror_scene("solid-angle"));
  const SceneView view = scene.view();
  test::InputStream s{3};
  for (int i = 0; i < 4096; ++i) {
    const float pick = s.next(), which = s.next(), u1 = s.next(), u2 = s.next();
    ASSERT_FALSE(sample_mirror_image(view, {-0.5f, 2.0f, 0.0f}, pick, which, u1, u2).valid);
    ASSERT_FALSE(sample_mirror_image(view, {0.0f, 2.0f, 0.0f}, pick, which, u1, u2).valid) << "on the plane";
  }
}

struct PixelMean {
  double mean, standard_error;
};

PixelMean floor_radiance(bool mirror_images) {
  RenderOverrides ov;
  ov.mirror_images = mirror_images ? Switch::On : Switch::Off;
  // the floor: a Lambert square at y = 0 around (2, 0, 0), behind the lamp's plane
  RenderStats stats;
  const Image img = render_cpu(
      test::scene_from(mirror_scene("solid-angle", R"(, {"type": "quad", "corner": [1.5, 0, -0.5], "u": [0, 0, 1],
                 "v": [1, 0, 0], "material": "floor"})"),
                       ov),
      0, stats);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  const size_t n = img.rgb.size() / 3;
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < n; ++i) sum += img.rgb[3 * i], sum2 += double(img.rgb[3 * i]) * img.rgb[3 * i];
  const double mean = sum / n, variance = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(variance / n)};
}

// Pixels are independent (stochastic sampler), so their spread gives the mean's standard error;
// five of them bound a correct renderer's failure below 1e-6. The camera's footprint is 0.035
// wide at (2, 0, 0), 1 % of the distance to the lamp's image: across it the irradiance varies
// far less than five standard errors (0.6 % of the mean with images).
TEST(MirrorImages, AFloorLitOffTheMirrorRendersItsClosedFormWithAndWithoutImages) {
  const double expected = 0.5 / kPi * irradiance_off_the_mirror({2.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
  const PixelMean with = floor_radiance(true), without = floor_radiance(false);
  EXPECT_NEAR(with.mean, expected, 5 * with.standard_error + 1e-6 * expected);
  EXPECT_NEAR(without.mean, expected, 5 * without.standard_error);
  // Measured (expected 0.014999): standard errors of 0.00059 without images and 0.000017 with
  // them, a variance about 1,200 times lower; at least 100 times lower holds with a wide margin.
  EXPECT_LT(with.standard_error * with.standard_error * 100, without.standard_error * without.standard_error);
}

// mirror_images draws its numbers past every bounce's own: where the scene has no planar
// mirror (only a mirror sphere), it changes no bit of the image.
TEST(MirrorImages, AScenePathWithoutPlanarMirrorsIsBitForBitTheSame) {
  const std::string scene =
      R"({"format": "tracer-scene/1", "camera": {"from": [0, 1, 4], "to": [0, 0.5, 0], "vfov": 50},
    "film": {"width": 24, "height": 16}, "render": {"integrator": "path", "spp": 4, "max_depth": 4},
    "materials": {"lamp": {"type": "emissive", "radiance": [4, 4, 4]},
                  "mirror": {"type": "metal", "albedo": [0.9, 0.9, 0.9], "roughness": 0},
                  "floor": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "quad", "corner": [-0.5, 2, -0.5], "u": [1, 0, 0], "v": [0, 0, 1], "material": "lamp"},
               {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "mirror"},
               {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})";
  RenderOverrides on, off;
  on.mirror_images = Switch::On;
  off.mirror_images = Switch::Off;
  RenderStats stats;
  const Scene with = test::scene_from(scene, on), without = test::scene_from(scene, off);
  EXPECT_EQ(with.view().mirror_count, 0u);
  EXPECT_EQ(with.features & kFeatureMirrorImages, 0u) << "nothing to sample: the kernel runs without the feature";
  EXPECT_EQ(with.settings.mirror_images, Switch::On) << "the loader leaves the setting as given";
  EXPECT_FALSE(recorded_options(with.settings, with.background.kind).to_json().contains("mirror_images"))
      << "at its default, the setting is not part of the render's identity";
  EXPECT_EQ(stream_bytes_per_state(with.view()), stream_bytes_per_state(without.view()))
      << "no stream arrays for mirror images without a mirror";
  EXPECT_EQ(render_cpu(with, 0, stats).rgb, render_cpu(without, 0, stats).rgb);
}

}  // namespace
}  // namespace tracer
