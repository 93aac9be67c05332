// What solid-angle sampling of a light shares between shapes (kernel/shading/spherical_rectangle.h,
// spherical_triangle.h): the range of solid angles sampled that way, and the float arc
// functions the solid angles are computed with.
#pragma once
#include "kernel/base/detmath.h"

namespace tracer {

// Outside [kSolidAngleSamplingMin, kSolidAngleSamplingMax] steradians a light is sampled by
// area instead, the same choice in light sampling and in the density MIS evaluates (light_pdf):
// below, a light far away, seen edge-on or from its own plane, where float loses the solid
// angle's precision (for a rectangle, a small difference of angles near pi / 2); above, a
// point almost on a large light.
constexpr float kSolidAngleSamplingMin = 1e-3f;
constexpr float kSolidAngleSamplingMax = 6.2f;

// The solid angle if the light is sampled in it, else 0 (sampled by area).
TRACER_HD float sampled_solid_angle(float omega) {
  return omega >= kSolidAngleSamplingMin && omega <= kSolidAngleSamplingMax ? omega : 0.0f;
}

// The polynomial c0 x^n + c1 x^(n-1) + ... + cn at x, by Horner's rule: p = c0, then p = p x + ci.
TRACER_HD float horner(float, float p) { return p; }

template <class... Rest>
TRACER_HD float horner(float x, float p, float c, Rest... rest) {
  return horner(x, p * x + c, rest...);
}

// acos in float for a spherical rectangle's angles: Abramowitz and Stegun 4.4.46, sqrt(1 - x)
// times a degree-7 polynomial on [0, 1] (|error| <= 2e-8), and acos(-x) = pi - acos(x); with
// float's rounding, within 3 ulps of the exact angle. det_acos's double-precision series made
// the light sample cost as much as the rest of a path vertex.
TRACER_HD float solid_angle_acos(float x) {
  const float a = abs_of(x);
  const float angle = det_sqrt(1.0f - a) * horner(a, -0.0012624911f, 0.0066700901f, -0.0170881256f, 0.0308918810f,
                                                  -0.0501743046f, 0.0889789874f, -0.2145988016f, 1.5707963050f);
  return x < 0.0f ? kPi - angle : angle;
}

// atan2(y, x) for y >= 0 in float: atan on [0, 1] by Abramowitz and Stegun 4.4.49, t times a
// degree-8 polynomial in t^2, |error| <= 2e-8 (relative 2e-8: it keeps small angles' precision),
// with atan(t) = pi / 2 - atan(1 / t) above 1 and pi - atan for x < 0. det_atan2's
// double-precision series made the solid angle cost as much as the sample itself.
TRACER_HD float solid_angle_atan2(float y, float x) {
  const float ax = abs_of(x);
  if (!(y > 0.0f || ax > 0.0f)) return 0.0f;
  const bool swapped = y > ax;
  const float t = swapped ? ax / y : y / ax, z = t * t;
  const float p = horner(z, 0.0028662257f, -0.0161657367f, 0.0429096138f, -0.0752896400f, 0.1065626393f, -0.1420889944f,
                         0.1999355085f, -0.3333314528f, 1.0f);
  const float angle = swapped ? 0.5f * kPi - t * p : t * p;
  return x < 0.0f ? kPi - angle : angle;
}

}  // namespace tracer
