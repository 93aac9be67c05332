// A Lambert plane under a point light, pixel by pixel against kd * I * cos / d^2 (Whitted)
// and albedo * I * cos / (pi d^2) (path tracing: next-event estimation at the first hit, the
// continuation escapes to a black sky), evaluated in double precision from the same camera rays.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_cpu.h"
#include "test_util.h"

using namespace tracer;

namespace {
const char* kScene = R"({"format": "tracer-scene/1",
  "camera": {"from": [0.2, 3, 4], "to": [0, 0, 0], "vfov": 50},
  "film": {"width": 64, "height": 48},
  "render": {"integrator": "INTEGRATOR", "spp": 1, "sampler": "center", "max_depth": DEPTH},
  "materials": {"floor": {"type": "lambert", "albedo": [0.5, 0.6, 0.7]}},
  "lights": [LIGHT],
  "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}]})";

// The float pipeline evaluates the answer with a few dozen roundings of at most 2^-24
// relative each (hit point, light vector, its length, normalisation, cosine, products);
// gamma(64) = 64 u / (1 - 64 u) bounds their compound relative error.
constexpr double kRelTolerance = 64 * 0x1p-24 / (1 - 64 * 0x1p-24);

void check_plane(const std::string& light, bool attenuated, bool path = false) {
  std::string text = kScene;
  text.replace(text.find("LIGHT"), 5, light);
  text.replace(text.find("INTEGRATOR"), 10, path ? "path" : "whitted");
  text.replace(text.find("DEPTH"), 5, path ? "1" : "0");
  const double brdf_scale = path ? 1.0 / M_PI : 1.0;  // Lambert's BRDF is albedo / pi
  const Scene scene = test::scene_from(text);
  RenderStats stats;
  const Image img = render_cpu(scene, 2, stats);
  const Light& l = scene.lights[0];
  const double kd[3] = {0.5, 0.6, 0.7}, I[3] = {l.intensity.x, l.intensity.y, l.intensity.z};
  int lit = 0;
  double worst = 0.0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      const Ray r = camera_ray(scene.camera, x + 0.5f, y + 0.5f, 0.5f, 0.5f);
      const float* px = &img.rgb[(y * img.width + x) * 3];
      if (!(r.dir.y < 0.0f)) {  // above the horizon: the black background
        EXPECT_EQ(px[0], 0.0f);
        continue;
      }
      const double t = -static_cast<double>(r.origin.y) / r.dir.y;
      const double p[3] = {r.origin.x + t * r.dir.x, 0.0, r.origin.z + t * r.dir.z};
      const double v[3] = {l.position.x - p[0], l.position.y - p[1], l.position.z - p[2]};
      const double d2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2], d = std::sqrt(d2);
      const double cos = v[1] / d;
      const double falloff = attenuated ? std::min(1.0 / (l.kc + l.kl * d + l.kq * d2), 1.0) : 1.0 / d2;
      for (int c = 0; c < 3; ++c) {
        const double expected = kd[c] * brdf_scale * I[c] * cos * falloff;
        const double rel = std::abs(px[c] - expected) / expected;
        worst = std::max(worst, rel);
        EXPECT_LE(rel, kRelTolerance) << "pixel " << x << "," << y << " channel " << c;
      }
      ++lit;
    }
  EXPECT_GT(lit, 1000);
  ::testing::Test::RecordProperty("max_relative_error", std::to_string(worst));
}
}  // namespace

TEST(LambertPlane, MatchesInverseSquareCosineLaw) {
  check_plane(R"({"type": "point", "position": [0.3, 2, -0.2], "intensity": [3, 4, 5]})", false);
}

TEST(LambertPlane, MatchesAttenuationPolynomial) {
  check_plane(
      R"({"type": "point", "position": [-0.5, 1.5, 0.5], "intensity": [2, 2, 2], "attenuation": [0.5, 0.3, 0.2]})",
      true);
}

TEST(LambertPlane, PathTracerMatchesAlbedoOverPi) {
  check_plane(R"({"type": "point", "position": [0.3, 2, -0.2], "intensity": [3, 4, 5]})", false, true);
}
