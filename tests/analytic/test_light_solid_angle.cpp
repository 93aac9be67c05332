// Rectangular lights sampled uniformly in solid angle (kernel/shading/spherical_rectangle.h):
// a chi-square test of where the samples land against each bin's share of the solid angle,
// E[1 / pdf] against the closed-form solid angle, the fallback to area sampling at the
// extremes (seen edge-on, from its own plane, from 1e6 away, from almost on it, a
// parallelogram), and the irradiance of Lambert's polygon formula with less variance than
// area sampling gives at the same sample count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

struct Rectangle {
  Vec3 corner, u, v;
  std::string json() const {
    return R"({"type": "quad", "corner": )" + test::json_array(corner) + R"(, "u": )" + test::json_array(u) +
           R"(, "v": )" + test::json_array(v) + R"(, "material": "lamp"})";
  }
  Vec3 at(double s, double t) const { return corner + u * float(s) + v * float(t); }
  // The solid angle of the part [s0, s1] x [t0, t1], as two triangles.
  double solid_angle(Vec3 from, double s0 = 0, double s1 = 1, double t0 = 0, double t1 = 1) const {
    return triangle_solid_angle(from, at(s0, t0), at(s1, t0), at(s1, t1)) +
           triangle_solid_angle(from, at(s0, t0), at(s1, t1), at(s0, t1));
  }
};

// The lamp of the Cornell box seen from beside and below it, an axis-free rectangle from
// close by, and a small one from afar.
const Rectangle kLamp = {{-0.5f, 2.0f, -0.5f}, {1, 0, 0}, {0, 0, 1}};
const Rectangle kTilted = {{0.2f, -0.3f, 0.1f}, {1.2f, 0.0f, 0.9f}, {0.0f, 1.5f, 0.0f}};

TEST(LightSolidAngle, RectangleSamplesAreUniformInSolidAngle) {
  const struct {
    Rectangle rect;
    Vec3 from;
  } cases[] = {{kLamp, {0.3f, 0.0f, 0.2f}},
               {kLamp, {1.7f, 1.8f, -0.9f}},
               {kTilted, {0.9f, 0.4f, -0.6f}},
               {{{-0.125f, 5.0f, -0.125f}, {0.25f, 0, 0}, {0, 0, 0.25f}}, {0.4f, 0.0f, 0.3f}}};
  for (const auto& c : cases) {
    const LightFixture fx(c.rect.json(), "solid-angle");
    const double omega = c.rect.solid_angle(c.from);
    ASSERT_GT(spherical_rectangle(c.from, c.rect.corner, c.rect.u, c.rect.v).solid_angle, 0.0f) << omega;
    constexpr int kBins = 12;
    std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, 0.0), by_area(kBins * kBins, 0.0);
    test::InputStream s{7};
    MeanEstimate inverse_pdf;
    for (int i = 0; i < kSamples; ++i) {
      const float u1 = s.next(), u2 = s.next();
      const LightSample ls = sample_light(fx.view, 0, c.from, u1, u2, 0.0f);
      ASSERT_TRUE(ls.valid) << u1 << " " << u2;
      inverse_pdf.add(1.0 / ls.pdf);
      const Vec3 q = c.from + ls.wi * ls.distance - c.rect.corner;
      const double sq = dot(q, c.rect.u) / dot(c.rect.u, c.rect.u), tq = dot(q, c.rect.v) / dot(c.rect.v, c.rect.v);
      const int bx = std::min(kBins - 1, std::max(0, int(sq * kBins))),
                by = std::min(kBins - 1, std::max(0, int(tq * kBins)));
      observed[by * kBins + bx] += 1;
      by_area[std::min(kBins - 1, int(u2 * kBins)) * kBins + std::min(kBins - 1, int(u1 * kBins))] += 1;
    }
    for (int by = 0; by < kBins; ++by)
      for (int bx = 0; bx < kBins; ++bx)
        expected[by * kBins + bx] = kSamples *
                                    c.rect.solid_angle(c.from, double(bx) / kBins, double(bx + 1) / kBins,
                                                       double(by) / kBins, double(by + 1) / kBins) /
                                    omega;
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
TEST(LightSolidAngle, ExtremesFallBackToAreaSamplingWithTheSameDensity) {
  const struct {
    const char* what;
    Rectangle rect;
    Vec3 from;
    bool sampled_by_solid_angle, valid;
  } cases[] = {
      {"from its own plane", kLamp, {2.0f, 2.0f, 0.0f}, false, false},
      {"seen nearly edge-on", kLamp, {3.0f, 1.999f, 0.0f}, false, true},
      {"1e6 away", kLamp, {1e6f, -1e6f, 3e5f}, false, true},
      {"almost on it", kLamp, {0.01f, 1.999999f, 0.02f}, false, true},
      {"a parallelogram", {{-0.5f, 2.0f, -0.5f}, {1, 0, 0}, {0.3f, 0, 1}}, {0.3f, 0.0f, 0.2f}, false, true},
      {"just above the threshold", {{-0.02f, 2.0f, -0.02f}, {0.04f, 0, 0}, {0, 0, 0.04f}}, {0, 0.8f, 0}, true, true},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const LightFixture fx(c.rect.json(), "solid-angle");
    const float omega = spherical_rectangle(c.from, c.rect.corner, c.rect.u, c.rect.v).solid_angle;
    EXPECT_EQ(omega > 0.0f, c.sampled_by_solid_angle) << omega;
    MeanEstimate inverse_pdf;
    test::expect_consistent_light_samples(fx, c.from, normalize(cross(c.rect.u, c.rect.v)), omega, c.valid,
                                          inverse_pdf);
    // Area sampling's density is right too: E[1 / pdf] is the solid angle (the parallelogram's
    // samples stay away from the grazing and near-zero distances whose 1 / pdf has no variance bound).
    if (std::string(c.what) == "a parallelogram") {
      EXPECT_NEAR(inverse_pdf.mean(), c.rect.solid_angle(c.from), inverse_pdf.tolerance());
    }
  }
}

// A point on the floor beside the lamp's edge, as in a Cornell box: both strategies estimate
// Lambert's answer, and the solid-angle one with at least 8x less variance at 65,536 samples
// (the ratio measured here is 17.4).
TEST(LightSolidAngle, PolygonIrradianceWithLessVarianceThanAreaSampling) {
  const Rectangle lamp = {{-0.5f, 1.0f, -0.5f}, {1, 0, 0}, {0, 0, 1}};
  const Vec3 x = {0.7f, 0.0f, 0.1f}, n = {0, 1, 0};
  const double exact = test::polygon_irradiance(x, n, {lamp.at(0, 0), lamp.at(1, 0), lamp.at(1, 1), lamp.at(0, 1)});
  const LightFixture fx(lamp.json(), "solid-angle");
  MeanEstimate solid, area;
  test::InputStream s{3};
  const float lamp_area = length(cross(lamp.u, lamp.v));
  for (int i = 0; i < 65536; ++i) {
    const float u1 = s.next(), u2 = s.next();
    const LightSample ls = sample_light(fx.view, 0, x, u1, u2, 0.0f);
    solid.add(ls.valid ? ls.radiance.x * std::max(0.0f, dot(n, ls.wi)) / ls.pdf : 0.0);
    const Vec3 to = lamp.at(u1, u2) - x;  // area sampling: pdf d^2 / (cos_l A) in solid angle
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
