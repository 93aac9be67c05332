// Triangular lights sampled uniformly in solid angle (kernel/shading/spherical_triangle.h,
// Arvo 1995): a chi-square test of where the samples land against each sub-triangle's share of
// the solid angle, E[1 / pdf] against the closed-form solid angle, the fallback to area
// sampling at the extremes (seen edge-on, from its own plane, from 1e6 away, from almost on
// it), and the irradiance of Lambert's polygon formula with less variance than area sampling
// gives at the same sample count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "chi2.h"
#include "kernel/light/light.h"
#include "light_fixture.h"

namespace tracer {
namespace {

using test::chi2_p_value;
using test::LightFixture;
using test::MeanEstimate;
using test::triangle_solid_angle;

constexpr double kSignificance = 1e-3;
constexpr int kSamples = 400000;

struct Triangle {
  Vec3 v0, v1, v2;
  std::string json() const {
    return R"({"type": "triangle", "vertices": [)" + test::json_array(v0) + ", " + test::json_array(v1) + ", " +
           test::json_array(v2) + R"(], "material": "lamp"})";
  }
  Vec3 at(double b1, double b2) const { return v0 * float(1 - b1 - b2) + v1 * float(b1) + v2 * float(b2); }
  Vec3 normal() const { return normalize(cross(v1 - v0, v2 - v0)); }
  // The barycentrics (b1, b2) of a point on the triangle, in double.
  void barycentrics(Vec3 p, double& b1, double& b2) const {
    const double e1[3] = {double(v1.x) - v0.x, double(v1.y) - v0.y, double(v1.z) - v0.z};
    const double e2[3] = {double(v2.x) - v0.x, double(v2.y) - v0.y, double(v2.z) - v0.z};
    const double r[3] = {double(p.x) - v0.x, double(p.y) - v0.y, double(p.z) - v0.z};
    const auto dot3 = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const double d11 = dot3(e1, e1), d12 = dot3(e1, e2), d22 = dot3(e2, e2), r1 = dot3(r, e1), r2 = dot3(r, e2);
    const double det = d11 * d22 - d12 * d12;
    b1 = (d22 * r1 - d12 * r2) / det;
    b2 = (d11 * r2 - d12 * r1) / det;
  }
};

// n x n sub-triangles of equal area: cell (i, j) of the barycentric grid, i + j < n, holds a
// lower sub-triangle and, where i + j < n - 1, an upper one.
int sub_triangle(double b1, double b2, int n) {
  const int j = std::clamp(int(b2 * n), 0, n - 1);
  const int i = std::min(std::clamp(int(b1 * n), 0, n - 1), n - 1 - j);  // rounding past the long edge
  const bool upper = i + j < n - 1 && (b1 * n - i) + (b2 * n - j) > 1.0;
  return (j * n + i) * 2 + (upper ? 1 : 0);
}

// The lamp-sized triangle of a Cornell box seen from beside and below it, a tilted one from
// close by (its solid angle 1.2 sr), and a small one from afar.
const Triangle kLamp = {{-0.5f, 2.0f, -0.5f}, {0.5f, 2.0f, -0.5f}, {-0.5f, 2.0f, 0.5f}};
const Triangle kTilted = {{0.2f, -0.3f, 0.1f}, {1.4f, -0.3f, 1.0f}, {0.2f, 1.2f, 0.4f}};

TEST(SphericalTriangle, SamplesAreUniformInSolidAngle) {
  const struct {
    Triangle tri;
    Vec3 from;
  } cases[] = {{kLamp, {0.3f, 0.0f, 0.2f}},
               {kLamp, {1.7f, 1.8f, -0.9f}},
               {kTilted, {0.9f, 0.4f, -0.6f}},
               {{{-0.125f, 5.0f, -0.125f}, {0.125f, 5.0f, -0.125f}, {0.0f, 5.0f, 0.2f}}, {0.4f, 0.0f, 0.3f}}};
  for (const auto& c : cases) {
    const LightFixture fx(c.tri.json(), "solid-angle");
    const double omega = triangle_solid_angle(c.from, c.tri.v0, c.tri.v1, c.tri.v2);
    ASSERT_GT(spherical_triangle(c.from, c.tri.v0, c.tri.v1, c.tri.v2).solid_angle, 0.0f) << omega;
    constexpr int kN = 10;
    std::vector<double> observed(2 * kN * kN, 0.0), expected(2 * kN * kN, 0.0), by_area(2 * kN * kN, 0.0);
    test::InputStream s{7};
    MeanEstimate inverse_pdf;
    for (int i = 0; i < kSamples; ++i) {
      const float u1 = s.next(), u2 = s.next();
      const LightSample ls = sample_light(fx.view, 0, c.from, u1, u2, 0.0f);
      ASSERT_TRUE(ls.valid) << u1 << " " << u2;
      inverse_pdf.add(1.0 / ls.pdf);
      double b1, b2;
      c.tri.barycentrics(c.from + ls.wi * ls.distance, b1, b2);
      observed[sub_triangle(b1, b2, kN)] += 1;
      float a1, a2;
      sample_triangle(u1, u2, a1, a2);
      by_area[sub_triangle(a1, a2, kN)] += 1;
    }
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i + j < kN; ++i) {
        const double h = 1.0 / kN, b1 = i * h, b2 = j * h;
        expected[(j * kN + i) * 2] =
            kSamples * triangle_solid_angle(c.from, c.tri.at(b1, b2), c.tri.at(b1 + h, b2), c.tri.at(b1, b2 + h)) /
            omega;
        if (i + j < kN - 1)
          expected[(j * kN + i) * 2 + 1] =
              kSamples *
              triangle_solid_angle(c.from, c.tri.at(b1 + h, b2), c.tri.at(b1 + h, b2 + h), c.tri.at(b1, b2 + h)) /
              omega;
      }
    // chi2_p_value pools the bins expected below 5 (the missing upper halves on the long edge).
    EXPECT_GT(chi2_p_value(observed, expected), kSignificance) << "from " << c.from.x << " " << c.from.y;
    // The test has power: beside the lamp, points uniform by area are not uniform in solid angle.
    if (&c == &cases[0]) {
      EXPECT_LT(chi2_p_value(by_area, expected), 1e-12);
    }
    // One light: the density is 1 / omega for every sample.
    EXPECT_NEAR(inverse_pdf.mean(), omega, 1e-4 * omega) << "from " << c.from.x << " " << c.from.y;
  }
}

// Where float cannot sample the solid angle, the light is sampled by area and light_pdf says
// the same density as the sample: every sample is finite, and valid wherever the light faces.
// From the light's own plane a sample is valid or not by rounding: the interpolated point can
// lie an ulp off the plane (a grazing, finite density).
TEST(SphericalTriangle, ExtremesFallBackToAreaSamplingWithTheSameDensity) {
  const Triangle small = {{-0.02f, 2.0f, -0.02f}, {0.04f, 2.0f, -0.02f}, {-0.02f, 2.0f, 0.04f}};
  const struct {
    const char* what;
    Triangle tri;
    Vec3 from;
    bool sampled_by_solid_angle, valid, rounding_decides = false;
  } cases[] = {
      {"from its own plane", kLamp, {2.0f, 2.0f, 0.0f}, false, false, true},
      {"seen nearly edge-on", kLamp, {3.0f, 1.999f, 0.0f}, false, true},
      {"1e6 away", kLamp, {1e6f, -1e6f, 3e5f}, false, true},
      {"almost on it", kLamp, {-0.2f, 1.999999f, -0.2f}, false, true},
      {"just below the threshold", small, {0, 0.6f, 0}, false, true},  // 0.92e-3 sr
      {"just above the threshold", small, {0, 0.72f, 0}, true, true},  // 1.10e-3 sr
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const LightFixture fx(c.tri.json(), "solid-angle");
    const float omega = spherical_triangle(c.from, c.tri.v0, c.tri.v1, c.tri.v2).solid_angle;
    EXPECT_EQ(omega > 0.0f, c.sampled_by_solid_angle) << triangle_solid_angle(c.from, c.tri.v0, c.tri.v1, c.tri.v2);
    MeanEstimate inverse_pdf;
    test::expect_consistent_light_samples(fx, c.from, c.tri.normal(), omega,
                                          c.rounding_decides ? std::nullopt : std::optional<bool>(c.valid),
                                          inverse_pdf);
    // Either way E[1 / pdf] is the solid angle (the small triangle's samples, by area or by
    // solid angle, stay away from the grazing distances whose 1 / pdf has no variance bound).
    if (c.tri.v0.x == small.v0.x) {
      EXPECT_NEAR(inverse_pdf.mean(), triangle_solid_angle(c.from, c.tri.v0, c.tri.v1, c.tri.v2),
                  inverse_pdf.tolerance());
    }
  }
}

// A point on the floor beside a triangular lamp's edge: both strategies estimate Lambert's
// answer, and the solid-angle one with at least 8x less variance at 65,536 samples (the ratio
// measured here is 17.2).
TEST(SphericalTriangle, PolygonIrradianceWithLessVarianceThanAreaSampling) {
  const Triangle lamp = {{-0.5f, 1.0f, -0.5f}, {0.5f, 1.0f, -0.5f}, {-0.5f, 1.0f, 0.5f}};
  const Vec3 x = {0.6f, 0.0f, -0.2f}, n = {0, 1, 0};
  const double exact = test::polygon_irradiance(x, n, {lamp.v0, lamp.v1, lamp.v2});
  const LightFixture fx(lamp.json(), "solid-angle");
  MeanEstimate solid, area;
  test::InputStream s{3};
  const float lamp_area = 0.5f * length(cross(lamp.v1 - lamp.v0, lamp.v2 - lamp.v0));
  for (int i = 0; i < 65536; ++i) {
    const float u1 = s.next(), u2 = s.next();
    const LightSample ls = sample_light(fx.view, 0, x, u1, u2, 0.0f);
    solid.add(ls.valid ? ls.radiance.x * std::max(0.0f, dot(n, ls.wi)) / ls.pdf : 0.0);
    float b1, b2;  // area sampling: pdf d^2 / (cos_l A) in solid angle
    sample_triangle(u1, u2, b1, b2);
    const Vec3 to = lamp.at(b1, b2) - x;
    const float d2 = dot(to, to), cos_x = dot(n, to) / std::sqrt(d2), cos_l = std::abs(to.y) / std::sqrt(d2);
    area.add(cos_x * cos_l * lamp_area / d2);
  }
  EXPECT_NEAR(solid.mean(), exact, solid.tolerance());
  EXPECT_NEAR(area.mean(), exact, area.tolerance());
  const double solid_var = solid.variance(), area_var = area.variance();
  EXPECT_GT(area_var / solid_var, 8.0) << "area " << area_var << ", solid angle " << solid_var;
  ::testing::Test::RecordProperty("variance_ratio", std::to_string(area_var / solid_var));
}

}  // namespace
}  // namespace tracer
