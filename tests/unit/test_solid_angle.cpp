// What solid-angle light sampling shares between shapes (kernel/shading/solid_angle.h): the
// float arc functions against the exact angle, and the range of solid angles sampled that way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kernel/shading/solid_angle.h"

namespace tracer {
namespace {

// The float atan2 the triangle's solid angle uses is within 3e-7 relative of the exact angle
// over [0, pi], down to angles of 1e-6 (a small triangle's solid angle keeps its precision).
TEST(SolidAngle, Atan2IsWithinFloatPrecisionOfTheExactAngle) {
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double angle = i < 1000 ? 1e-6 * std::pow(1e6, i / 1000.0) : kPiD * (i - 1000) / 199000.0;
    const float y = float(std::sin(angle) * 3.0), x = float(std::cos(angle) * 3.0);
    const double exact = std::atan2(double(y), double(x));
    if (exact <= 0) continue;
    worst = std::max(worst, std::abs(solid_angle_atan2(y, x) - exact) / exact);
  }
  EXPECT_LT(worst, 3e-7);
  EXPECT_EQ(solid_angle_atan2(0.0f, 0.0f), 0.0f);
  EXPECT_EQ(solid_angle_atan2(0.0f, -1.0f), kPi);
}

// The float acos the rectangle's angles use is within 3 ulps of the exact angle over [-1, 1]
// (2.84 at worst: the polynomial's 2e-8, float's rounding of each step and of pi - angle).
TEST(SolidAngle, AcosIsWithinThreeUlpsOfTheExactAngle) {
  double worst_ulps = 0;
  for (int i = 0; i <= 200000; ++i) {
    const float x = float(-1.0 + 2.0 * i / 200000.0);
    const double exact = std::acos(double(x));
    const double ulp = std::nextafter(float(exact), 4.0f) - float(exact);
    worst_ulps = std::max(worst_ulps, std::abs(solid_angle_acos(x) - exact) / ulp);
  }
  EXPECT_LT(worst_ulps, 3.0);
  EXPECT_EQ(solid_angle_acos(1.0f), 0.0f);
  EXPECT_EQ(solid_angle_acos(-1.0f), kPi);
}

// Both shapes are sampled in solid angle on the same closed range, by area outside it.
TEST(SolidAngle, OneRangeDecidesBetweenSolidAngleAndArea) {
  EXPECT_EQ(sampled_solid_angle(kSolidAngleSamplingMin), kSolidAngleSamplingMin);
  EXPECT_EQ(sampled_solid_angle(kSolidAngleSamplingMax), kSolidAngleSamplingMax);
  EXPECT_EQ(sampled_solid_angle(1.0f), 1.0f);
  EXPECT_EQ(sampled_solid_angle(std::nextafter(kSolidAngleSamplingMin, 0.0f)), 0.0f);
  EXPECT_EQ(sampled_solid_angle(std::nextafter(kSolidAngleSamplingMax, 7.0f)), 0.0f);
  EXPECT_EQ(sampled_solid_angle(0.0f), 0.0f);
  EXPECT_EQ(sampled_solid_angle(std::nanf("")), 0.0f);
}

}  // namespace
}  // namespace tracer
