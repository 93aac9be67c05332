// Spot lights and the sun (kernel/light/spot_light.h, directional_light.h) against closed
// forms: a Lambert plane under a spot, pixel by pixel inside its inner cone, in its falloff and
// outside (kd I f(angle) cos / d^2), the spot's power against the quadrature of its factor; a
// plane under a parallel sun (E cos theta) and under a sun disc, whose irradiance is still
// E cos theta wherever the whole disc is above the horizon, found by light samples and by BSDF
// samples alone; the sun's cone sampler by chi-square and E[1 / pdf]; the readers' refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "chi2.h"
#include "kernel/light/light.h"
#include "light_fixture.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

// The plane y = 0 seen from above, lit by LIGHT alone; a black sky.
std::string plane_scene(const std::string& light, const std::string& render) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0.2, 3, 4], "to": [0, 0, 0], "vfov": 60},
    "film": {"width": 64, "height": 48}, "render": )" +
         render + R"(, "materials": {"floor": {"type": "lambert", "albedo": [0.5, 0.6, 0.7]}},
    "lights": [)" +
         light + R"(], "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})";
}
constexpr double kAlbedo[3] = {0.5, 0.6, 0.7};
const std::string kWhitted = R"({"integrator": "whitted", "spp": 1, "sampler": "center", "max_depth": 0})";
const std::string kPathNee = R"({"integrator": "path", "spp": 1, "sampler": "center", "max_depth": 1})";

// As test_lambert_plane.cpp: a few dozen roundings of at most 2^-24 relative each.
constexpr double kRelTolerance = 64 * 0x1p-24 / (1 - 64 * 0x1p-24);
// The kernel's cosine to the spot's axis is within 64 units of 2^-24 of the exact one: the hit
// point's rounding (a few units relative to its distance from the camera, about 5) moves the
// direction to the light (about 2 away) by up to about 8 units, and the light vector, its
// normalisation and the dot product add their own.
constexpr double kCosError = 64 * 0x1p-24;

// The double-precision point of the plane that pixel (x, y)'s centre ray meets.
bool floor_point(const Scene& scene, uint32_t x, uint32_t y, double p[3]) {
  const Ray r = camera_ray(scene.camera, x + 0.5f, y + 0.5f, 0.5f, 0.5f);
  if (!(r.dir.y < 0.0f)) return false;
  const double t = -static_cast<double>(r.origin.y) / r.dir.y;
  p[0] = r.origin.x + t * r.dir.x, p[1] = 0.0, p[2] = r.origin.z + t * r.dir.z;
  return true;
}

struct SpotRegions {
  int inside = 0, falloff = 0, outside = 0;
};

SpotRegions check_spot_plane(const std::string& render, double brdf_scale) {
  const Scene scene = test::scene_from(plane_scene(R"({"type": "spot", "position": [0.2, 2, -0.3],
      "direction": [0.1, -1, 0.2], "intensity": [3, 4, 5], "inner_angle": 25, "outer_angle": 40})",
                                                   render));
  RenderStats stats;
  const Image img = render_cpu(scene, 2, stats);
  const Light& l = scene.lights[0];
  const double ci = l.cos_inner, co = l.cos_outer;
  SpotRegions regions;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      double p[3];
      if (!floor_point(scene, x, y, p)) continue;
      const double v[3] = {l.position.x - p[0], l.position.y - p[1], l.position.z - p[2]};
      const double d2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2], d = std::sqrt(d2);
      const double c = -(v[0] * l.direction.x + v[1] * l.direction.y + v[2] * l.direction.z) / d;
      if (std::abs(c - ci) <= kCosError || std::abs(c - co) <= kCosError) continue;  // rounding decides
      const float* px = &img.rgb[(y * img.width + x) * 3];
      if (c < co) {
        ++regions.outside;
        EXPECT_EQ(px[0] + px[1] + px[2], 0.0f) << "pixel " << x << "," << y << " lies outside the outer cone";
        continue;
      }
      const double t = (c - co) / (ci - co), factor = c > ci ? 1.0 : t * t;
      // in the falloff, the cosine's error gives t^2 a relative error of 2 kCosError / (c - co)
      const double tolerance = kRelTolerance + (c > ci ? 0.0 : 2.0 * kCosError / (c - co));
      ++(c > ci ? regions.inside : regions.falloff);
      for (int k = 0; k < 3; ++k) {
        const double I = k == 0 ? l.intensity.x : k == 1 ? l.intensity.y : l.intensity.z;
        const double expected = kAlbedo[k] * brdf_scale * I * factor * (v[1] / d) / d2;
        EXPECT_LE(std::abs(px[k] - expected), tolerance * expected) << "pixel " << x << "," << y << " channel " << k;
      }
    }
  return regions;
}

TEST(SpotLight, LambertPlaneInsideTheInnerConeInTheFalloffAndOutside) {
  const SpotRegions whitted = check_spot_plane(kWhitted, 1.0);
  EXPECT_GT(whitted.inside, 100);
  EXPECT_GT(whitted.falloff, 100);
  EXPECT_GT(whitted.outside, 100);
  const SpotRegions path = check_spot_plane(kPathNee, 1.0 / M_PI);  // Lambert's BRDF is albedo / pi
  EXPECT_EQ(path.falloff, whitted.falloff);
}

// The power that chooses a spot in the light table is 2 pi I times the integral of its factor
// over the cosine; the factor itself, integrated by the midpoint rule in the cosine, agrees.
TEST(SpotLight, PowerIsTheIntegralOfItsFactor) {
  for (const auto& [inner, outer] : std::vector<std::pair<int, int>>{{0, 45}, {20, 35}, {30, 30}, {10, 90}}) {
    const Scene scene = test::scene_from(plane_scene(R"({"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
        "intensity": [1, 1, 1], "inner_angle": )" + std::to_string(inner) +
                                                         R"(, "outer_angle": )" + std::to_string(outer) + "}",
                                                     kWhitted));
    const Light& l = scene.lights[0];
    const int steps = 1 << 20;
    double integral = 0.0;
    for (int i = 0; i < steps; ++i) {
      const double c = -1.0 + 2.0 * (i + 0.5) / steps, s = std::sqrt(1.0 - c * c);
      integral += spot_factor(l, {static_cast<float>(s), static_cast<float>(-c), 0.0f}) * 2.0 / steps;
    }
    // Each step's factor is within a float's rounding; the midpoint rule's error at the cone's
    // two kinks is of the order of a step (2^-19) times the factor's slope there.
    EXPECT_NEAR(light_power(l, 1.0), 2.0 * M_PI * integral, 2.0 * M_PI * 1e-4) << inner << " to " << outer;
  }
}

TEST(SunLight, ParallelLightOnALambertPlaneIsECosTheta) {
  for (const auto& [render, brdf_scale] :
       std::vector<std::pair<std::string, double>>{{kWhitted, 1.0}, {kPathNee, 1.0 / M_PI}}) {
    const Scene scene = test::scene_from(
        plane_scene(R"({"type": "directional", "direction": [-0.3, -1, -0.5], "irradiance": [3, 4, 5]})", render));
    RenderStats stats;
    const Image img = render_cpu(scene, 2, stats);
    const Light& l = scene.lights[0];
    const double cos_theta = -static_cast<double>(l.direction.y);
    int lit = 0;
    for (uint32_t y = 0; y < img.height; ++y)
      for (uint32_t x = 0; x < img.width; ++x) {
        double p[3];
        if (!floor_point(scene, x, y, p)) continue;
        ++lit;
        for (int k = 0; k < 3; ++k) {
          const double E = k == 0 ? l.intensity.x : k == 1 ? l.intensity.y : l.intensity.z;
          const double expected = kAlbedo[k] * brdf_scale * E * cos_theta;
          EXPECT_LE(std::abs(img.rgb[(y * img.width + x) * 3 + k] - expected), kRelTolerance * expected)
              << "pixel " << x << "," << y << " channel " << k;
        }
      }
    EXPECT_GT(lit, 1000);
  }
}

// A sun disc of 30 degrees whose centre is 40 degrees from the normal: the whole disc is above
// the horizon, so the plane's irradiance is E cos 40 degrees at every point, and the image is
// flat at albedo / pi times it. Light samples (NEE, MIS against the BSDF) and BSDF samples
// alone (nee off: a path leaving the scene inside the disc meets it) both converge to it; each
// pixel is an independent estimate, so the image's mean is held to its own standard error.
TEST(SunLight, DiscSunGivesECosThetaByLightAndByBsdfSamples) {
  const double theta = 40.0 * M_PI / 180.0;
  const std::string sun = R"({"type": "directional", "direction": [)" + std::to_string(-std::sin(theta)) + ", " +
                          std::to_string(-std::cos(theta)) + R"(, 0], "irradiance": [2, 2, 2], "angle": 30})";
  for (const char* nee : {"true", "false"}) {
    const Scene scene = test::scene_from(plane_scene(
        sun, std::string(R"({"integrator": "path", "spp": 256, "sampler": "stochastic", "max_depth": 1, "nee": )") +
                 nee + "}"));
    RenderStats stats;
    const Image img = render_cpu(scene, 2, stats);
    const double cos_theta = -static_cast<double>(scene.lights[0].direction.y);
    test::MeanEstimate mean;
    for (uint32_t y = 0; y < img.height; ++y)
      for (uint32_t x = 0; x < img.width; ++x) {
        double p[3];
        if (floor_point(scene, x, y, p)) mean.add(img.rgb[(y * img.width + x) * 3] / (kAlbedo[0] / M_PI * 2.0));
      }
    ASSERT_GT(mean.n, 1000);
    EXPECT_NEAR(mean.mean(), cos_theta, mean.tolerance()) << "nee " << nee;
  }
}

// The sun disc's directions are uniform in its cone, and E[1 / pdf] is its solid angle.
TEST(SunLight, DiscSamplesAreUniformInTheCone) {
  const Scene scene = test::scene_from(plane_scene(
      R"({"type": "directional", "direction": [0.3, -1, 0.2], "irradiance": [1, 1, 1], "angle": 20})", kPathNee));
  const SceneView view = scene.view();
  const Light& l = scene.lights[0];
  const double one_minus_cos = l.one_minus_cos, cos_max = 1.0 - one_minus_cos;
  const Frame f = frame_around(-l.direction);
  const int cos_bins = 16, phi_bins = 24, samples = 400000;
  std::vector<double> observed(cos_bins * phi_bins, 0.0),
      expected(cos_bins * phi_bins, static_cast<double>(samples) / (cos_bins * phi_bins));
  test::InputStream s{5};
  test::MeanEstimate inverse_pdf;
  for (int i = 0; i < samples; ++i) {
    const float u1 = s.next(), u2 = s.next();
    const LightSample ls = sample_light(view, 0, {0, 0, 0}, u1, u2, 0.0f);
    ASSERT_TRUE(ls.valid && !ls.delta);
    inverse_pdf.add(1.0 / ls.pdf);
    const double c = dot(ls.wi, f.n), phi = std::atan2(dot(ls.wi, f.b), dot(ls.wi, f.t)) + M_PI;
    const int ci = std::min(cos_bins - 1, std::max(0, static_cast<int>((c - cos_max) / one_minus_cos * cos_bins)));
    observed[ci * phi_bins + std::min(phi_bins - 1, static_cast<int>(phi / (2 * M_PI) * phi_bins))] += 1;
  }
  EXPECT_GT(test::chi2_p_value(observed, expected), 1e-3);
  EXPECT_NEAR(inverse_pdf.mean(), 2 * M_PI * one_minus_cos, 1e-5 * 2 * M_PI * one_minus_cos);
}

TEST(SpotAndSun, TheSceneFileRefusesWhatHasNoMeaning) {
  const auto dir = test::temp_dir("spot-and-sun");
  const auto refused = [&](const std::string& light, const std::string& expected) {
    test::expect_load_error(dir, plane_scene(light, kWhitted), expected);
  };
  refused(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, 0, 0], "intensity": [1, 1, 1]})",
          "lights[0].direction: expected a finite, non-zero direction");
  refused(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1],
      "inner_angle": 40, "outer_angle": 30})",
          "lights[0].outer_angle: expected cone half-angles 0 <= inner <= outer <= 90 degrees");
  refused(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1],
      "outer_angle": 100})",
          "lights[0].outer_angle: expected cone half-angles");
  refused(R"({"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "angle": 0.001})",
          "lights[0].angle: expected an angular diameter of 0 (parallel light) or 0.01 to 180 degrees");
  refused(R"({"type": "directional", "direction": [0, -1, 0], "irradiance": [1e38, 1, 1], "angle": 0.02})",
          "lights[0].angle: the disc's radiance");
  refused(R"({"type": "directional", "direction": [0, -1, 0], "intensity": [1, 1, 1]})", "irradiance");
}

}  // namespace
}  // namespace tracer
