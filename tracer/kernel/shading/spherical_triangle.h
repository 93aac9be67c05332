// Solid-angle sampling of a triangular light (Arvo 1995, "Stratified Sampling of Spherical
// Triangles", SIGGRAPH): directions uniform in the solid angle the triangle subtends from a
// point, the triangle's counterpart of kernel/shading/spherical_rectangle.h.
//
// Where float would lose the construction's precision, the light is sampled by area instead
// (kernel/shading/solid_angle.h): solid angles outside the range sampled that way.
#pragma once
#include "kernel/base/vec3.h"
#include "kernel/shading/solid_angle.h"

namespace tracer {

// The triangle as seen from a point: its solid angle and, where that is > 0, the unit directions
// to its vertices.
struct SphericalTriangle {
  Vec3 a, b, c;
  float solid_angle;  // in steradians; 0 where the light is sampled by area
};

// Triangle (v0, v1, v2) from `from`. Van Oosterom and Strackee (1983): tan(omega / 2) =
// |A . (B x C)| / (|A||B||C| + (A.B)|C| + (A.C)|B| + (B.C)|A|) for A = v0 - from ..., with
// A . (B x C) taken as A . ((v1 - v0) x (v2 - v0)), the distance to the plane times twice the
// area, which keeps its precision for a small triangle.
TRACER_HD SphericalTriangle spherical_triangle(Vec3 from, Vec3 v0, Vec3 v1, Vec3 v2) {
  const Vec3 a = v0 - from, b = v1 - from, c = v2 - from;
  const float la = length(a), lb = length(b), lc = length(c);
  if (!(la > 0.0f && lb > 0.0f && lc > 0.0f)) return {a, b, c, 0.0f};
  const float triple = abs_of(dot(a, cross(v1 - v0, v2 - v0)));
  const float denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  const float omega = 2.0f * solid_angle_atan2(triple, denominator);
  return {a / la, b / lb, c / lc, sampled_solid_angle(omega)};
}

// The direction's barycentrics (b1, b2) on triangle (v0, v1, v2) for (u1, u2) in [0, 1)^2,
// uniformly in the solid angle it subtends from `from` (`st`, with solid_angle > 0; Arvo's
// algorithm: u1 picks the sub-triangle (a, b, c') of area u1 omega, u2 the point on the arc
// from b to c').
TRACER_HD void sample_spherical_triangle(const SphericalTriangle& st, Vec3 from, Vec3 v0, Vec3 v1, Vec3 v2, float u1,
                                         float u2, float& b1, float& b2) {
  const Vec3 a = st.a, b = st.b, c = st.c;
  const float omega = st.solid_angle;
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
