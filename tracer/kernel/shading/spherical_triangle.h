// Solid-angle sampling of a triangular light (Arvo 1995, "Stratified Sampling of Spherical
// Triangles", SIGGRAPH): directions uniform in the solid angle the triangle subtends from a
// point, the triangle's counterpart of kernel/shading/spherical_rectangle.h.
//
// Where float would lose the construction's precision, the light is sampled by area instead,
// the same choice in light sampling and in the density MIS evaluates (light_pdf): solid angles
// outside [kSphericalTriangleMin, kSphericalTriangleMax] steradians (below: a light far away,
// seen edge-on or from its own plane; above: a point almost on a large light).
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/vec3.h"

namespace tracer {

constexpr float kSphericalTriangleMin = 1e-3f;
constexpr float kSphericalTriangleMax = 6.2f;

// atan2(y, x) for y >= 0 in float: atan on [0, 1] by Abramowitz and Stegun 4.4.49, t times a
// degree-8 polynomial in t^2, |error| <= 2e-8 (relative 2e-8: it keeps small angles' precision),
// with atan(t) = pi / 2 - atan(1 / t) above 1 and pi - atan for x < 0. det_atan2's
// double-precision series made the solid angle cost as much as the sample itself.
TRACER_HD float solid_angle_atan2(float y, float x) {
  const float ax = abs_of(x);
  if (!(y > 0.0f || ax > 0.0f)) return 0.0f;
  const bool swapped = y > ax;
  const float t = swapped ? ax / y : y / ax, z = t * t;
  float p = 0.0028662257f;
  p = p * z - 0.0161657367f;
  p = p * z + 0.0429096138f;
  p = p * z - 0.0752896400f;
  p = p * z + 0.1065626393f;
  p = p * z - 0.1420889944f;
  p = p * z + 0.1999355085f;
  p = p * z - 0.3333314528f;
  p = p * z + 1.0f;
  const float angle = swapped ? 0.5f * kPi - t * p : t * p;
  return x < 0.0f ? kPi - angle : angle;
}

// The solid angle triangle (v0, v1, v2) subtends from `from`, or 0 where it is sampled by area.
// Van Oosterom and Strackee (1983): tan(omega / 2) = |A . (B x C)| / (|A||B||C| + (A.B)|C| +
// (A.C)|B| + (B.C)|A|) for A = v0 - from ..., with A . (B x C) taken as A . ((v1 - v0) x (v2 - v0)),
// the distance to the plane times twice the area, which keeps its precision for a small triangle.
TRACER_HD float spherical_triangle_solid_angle(Vec3 from, Vec3 v0, Vec3 v1, Vec3 v2) {
  const Vec3 a = v0 - from, b = v1 - from, c = v2 - from;
  const float la = length(a), lb = length(b), lc = length(c);
  if (!(la > 0.0f && lb > 0.0f && lc > 0.0f)) return 0.0f;
  const float triple = abs_of(dot(a, cross(v1 - v0, v2 - v0)));
  const float denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  const float omega = 2.0f * solid_angle_atan2(triple, denominator);
  return omega >= kSphericalTriangleMin && omega <= kSphericalTriangleMax ? omega : 0.0f;
}

// The direction's barycentrics (b1, b2) on triangle (v0, v1, v2) for (u1, u2) in [0, 1)^2,
// uniformly in the solid angle omega > 0 it subtends from `from` (Arvo's algorithm: u1 picks
// the sub-triangle (a, b, c') of area u1 omega, u2 the point on the arc from b to c').
TRACER_HD void sample_spherical_triangle(Vec3 from, Vec3 v0, Vec3 v1, Vec3 v2, float omega, float u1, float u2,
                                         float& b1, float& b2) {
  const Vec3 a = normalize(v0 - from), b = normalize(v1 - from), c = normalize(v2 - from);
  // The angle alpha at vertex a between the arcs to b and to c, from their tangents at a,
  // t_b = b - (a.b) a = db - (a.db) a with db = b - a (no cancellation for a small triangle):
  // |t_b x t_c| = |a . (b x c)|.
  const Vec3 db = b - a, dc = c - a;
  const float sin_part = abs_of(dot(a, cross(db, dc)));
  const float cos_part = dot(db, dc) - dot(a, db) * dot(a, dc);
  const float hypot = det_sqrt(sin_part * sin_part + cos_part * cos_part);
  const float sin_alpha = sin_part / hypot, cos_alpha = cos_part / hypot;
  // The sub-triangle's third vertex c' on the arc from a to c (Arvo's equations for q).
  float sin_area, cos_area;
  det_sincos(u1 * omega, sin_area, cos_area);
  const float s = sin_area * cos_alpha - cos_area * sin_alpha;  // sin(A' - alpha)
  const float t = cos_area * cos_alpha + sin_area * sin_alpha;  // cos(A' - alpha)
  const float uu = t - cos_alpha, vv = s + sin_alpha * dot(a, b);
  const float q = clamp_of(((vv * t - uu * s) * cos_alpha - vv) / ((vv * s + uu * t) * sin_alpha), -1.0f, 1.0f);
  const Vec3 c_prime = a * q + normalize(c - a * dot(c, a)) * det_sqrt(max_of(1.0f - q * q, 0.0f));
  // The direction on the arc from b to c', uniform in the cosine of its angle from b.
  const float z = 1.0f - u2 * (1.0f - dot(c_prime, b));
  const Vec3 along = c_prime - b * dot(c_prime, b);
  const float along_length = length(along);
  const Vec3 w = along_length > 0.0f ? b * z + along * (det_sqrt(max_of(1.0f - z * z, 0.0f)) / along_length) : b;
  // Where w meets the triangle's plane, in barycentrics, clamped onto the triangle.
  const Vec3 e1 = v1 - v0, e2 = v2 - v0, n = cross(e1, e2);
  const float nn = dot(n, n), wn = dot(w, n);
  b1 = 0.0f, b2 = 0.0f;
  if (!(abs_of(wn) > 0.0f && nn > 0.0f)) return;
  const Vec3 r = w * (dot(v0 - from, n) / wn) - (v0 - from);  // the point minus v0
  b1 = max_of(dot(cross(r, e2), n) / nn, 0.0f);
  b2 = max_of(dot(cross(e1, r), n) / nn, 0.0f);
  const float sum = b1 + b2;
  if (sum > 1.0f) b1 /= sum, b2 /= sum;
}

}  // namespace tracer
