// What the light-sampling tests share: a scene holding one emitter, a Monte Carlo mean with
// the tolerance its own noise allows, the closed-form solid angle of a triangle and the
// closed-form irradiance from a polygon, and the checks every light sample must pass.
#pragma once
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/light/light.h"
#include "scene/scene.h"
#include "test_util.h"

namespace tracer::test {

// One emitter in a scene, sampled from `from`.
struct LightFixture {
  Scene scene;
  SceneView view;
  // light_sampling: render.light_sampling, "area" (the default) or "solid-angle".
  explicit LightFixture(const std::string& shape, const std::string& light_sampling = "area")
      : scene(scene_from(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
          "film": {"width": 4, "height": 4}, "render": {"integrator": "path", "light_sampling": ")" +
                         light_sampling + R"("},
          "materials": {"lamp": {"type": "emissive", "radiance": [1, 1, 1], "two_sided": true}},
          "shapes": [)" + shape +
                         "]}")),
        view(scene.view()) {}
};

// A Monte Carlo mean and the tolerance its own noise allows: z standard errors, z = 3.29 for
// a two-sided false-failure probability of 1e-3, plus 1e-5 relative for the float
// rounding of the densities summed (a constant density has no variance at all).
struct MeanEstimate {
  double sum = 0, sum2 = 0;
  long n = 0;
  void add(double x) { sum += x, sum2 += x * x, ++n; }
  double mean() const { return sum / n; }
  double variance() const { return std::max(0.0, sum2 / n - mean() * mean()); }
  double tolerance() const { return 3.29 * std::sqrt(variance() / n) + 1e-5 * std::abs(mean()); }
};

// 4,096 samples of the fixture's one light from `from` (its geometric normal ng): each valid
// one finite, with the density light_pdf gives its direction bit for bit, and 1 / omega where
// the light is sampled in solid angle (omega > 0). `valid`: whether every sample is valid or
// none is; no value where rounding decides. Adds each valid sample's 1 / pdf to inverse_pdf.
inline void expect_consistent_light_samples(const LightFixture& fx, Vec3 from, Vec3 ng, float omega,
                                            std::optional<bool> valid, MeanEstimate& inverse_pdf) {
  InputStream s{11};
  for (int i = 0; i < 4096; ++i) {
    const float u1 = s.next(), u2 = s.next();
    const LightSample ls = sample_light(fx.view, 0, from, u1, u2, 0.0f);
    if (valid) {
      ASSERT_EQ(ls.valid, *valid) << u1 << " " << u2;
    }
    if (!ls.valid) continue;
    inverse_pdf.add(1.0 / ls.pdf);
    ASSERT_TRUE(std::isfinite(ls.pdf) && ls.pdf > 0.0f && is_finite(ls.wi) && std::isfinite(ls.distance));
    ASSERT_EQ(shape_light_pdf(fx.view, 0, from, ls.wi, ls.distance, ng), ls.pdf) << u1 << " " << u2;
    if (omega > 0.0f) {
      ASSERT_EQ(ls.pdf, 1.0f / omega);
    }
  }
}

// Solid angle of triangle (a, b, c) seen from p (Van Oosterom and Strackee 1983):
// tan(omega / 2) = |A . (B x C)| / (|A||B||C| + (A.B)|C| + (A.C)|B| + (B.C)|A|), A = a - p ...
inline double triangle_solid_angle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const double A[3] = {double(a.x) - p.x, double(a.y) - p.y, double(a.z) - p.z};
  const double B[3] = {double(b.x) - p.x, double(b.y) - p.y, double(b.z) - p.z};
  const double C[3] = {double(c.x) - p.x, double(c.y) - p.y, double(c.z) - p.z};
  const auto dot3 = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double triple =
      A[0] * (B[1] * C[2] - B[2] * C[1]) - A[1] * (B[0] * C[2] - B[2] * C[0]) + A[2] * (B[0] * C[1] - B[1] * C[0]);
  const double la = std::sqrt(dot3(A, A)), lb = std::sqrt(dot3(B, B)), lc = std::sqrt(dot3(C, C));
  const double denominator = la * lb * lc + dot3(A, B) * lc + dot3(A, C) * lb + dot3(B, C) * la;
  return 2 * std::atan2(std::abs(triple), denominator);
}

// A point as a scene file's JSON array.
inline std::string json_array(Vec3 a) {
  return "[" + std::to_string(a.x) + ", " + std::to_string(a.y) + ", " + std::to_string(a.z) + "]";
}

// Irradiance at x (normal n) from a polygon of radiance 1, Lambert's formula:
// E = 1/2 sum_i theta_i n . normalize(R_i x R_i+1), R_i the unit directions to the corners.
inline double polygon_irradiance(Vec3 x, Vec3 n, std::initializer_list<Vec3> polygon) {
  const std::vector<Vec3> corners(polygon);
  double sum = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = normalize(corners[i] - x), b = normalize(corners[(i + 1) % corners.size()] - x);
    sum += std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0)) * dot(n, normalize(cross(a, b)));
  }
  return 0.5 * std::abs(sum);
}

}  // namespace tracer::test
