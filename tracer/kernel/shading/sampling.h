// Warps of uniform numbers in [0,1)^2 to directions and points, with their densities.
// Each is checked by a chi-square goodness-of-fit test (tests/analytic/test_sampling_chi2.cpp).
#pragma once
#include <glm/mat3x3.hpp>

#include "kernel/base/detmath.h"
#include "kernel/base/vec3.h"

namespace tracer {

// An orthonormal frame around unit n (Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 2017), branch-free but for the sign. to_world is the matrix with columns
// t, b, n times v (GLM sums (t v.x + b v.y) + n v.z per component); to_local its transpose.
struct Frame {
  Vec3 t, b, n;
  TRACER_HD Vec3 to_world(Vec3 v) const { return glm::mat3(t, b, n) * v; }
  TRACER_HD Vec3 to_local(Vec3 v) const { return {dot(v, t), dot(v, b), dot(v, n)}; }
};

TRACER_HD Frame frame_around(Vec3 n) {
  const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  return {{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
}

// Direction at polar angle acos(cos_theta) and azimuth 2 pi u about +z.
TRACER_HD Vec3 direction_from(float cos_theta, float u) {
  const float sin_theta = det_sqrt(max_of(0.0f, 1.0f - cos_theta * cos_theta));
  float sin_phi, cos_phi;
  det_sincos(2.0f * kPi * u, sin_phi, cos_phi);
  return {sin_theta * cos_phi, sin_theta * sin_phi, cos_theta};
}

// Cosine-weighted hemisphere about +z (Malley's method with the polar disk map):
// pdf = cos(theta) / pi.
TRACER_HD Vec3 sample_cosine_hemisphere(float u1, float u2) { return direction_from(det_sqrt(1.0f - u1), u2); }

// A Phong lobe cos^e(alpha) about +z: cos(alpha) = u1^(1/(e+1)), pdf = (e+1)/(2 pi) cos^e.
TRACER_HD Vec3 sample_phong_lobe(float exponent, float u1, float u2) {
  return direction_from(det_pow(1.0f - u1, 1.0f / (exponent + 1.0f)), u2);
}

TRACER_HD float phong_lobe_pdf(float exponent, float cos_alpha) {
  if (!(cos_alpha > 0.0f)) return 0.0f;
  return (exponent + 1.0f) / (2.0f * kPi) * det_pow(cos_alpha, exponent);
}

// Uniform in the cone of half-angle theta_max about +z, given 1 - cos(theta_max) (which
// callers compute without cancellation): pdf = 1 / (2 pi (1 - cos_max)).
TRACER_HD Vec3 sample_cone(float one_minus_cos_max, float u1, float u2) {
  return direction_from(1.0f - u1 * one_minus_cos_max, u2);
}

// Uniform on a triangle: weights (b1, b2) = sqrt(u1) (1 - u2, u2) of v1 and v2 (Osada et al. 2002).
TRACER_HD void sample_triangle(float u1, float u2, float& b1, float& b2) {
  const float s = det_sqrt(u1);
  b1 = s * (1.0f - u2);
  b2 = s * u2;
}

// The index of the first entry whose cdf exceeds u (entries[count - 1].cdf is 1; the last
// index if rounding leaves none): drawing an entry of a discrete distribution given a
// uniform u. A branch-free binary search (the step is a conditional move, not a jump the
// CPU mispredicts half the time on a random u): the first `base` entries have cdf <= u.
template <class Entry>
TRACER_HD uint32_t find_cdf_interval(const Entry* entries, uint32_t count, float u) {
  uint32_t base = 0, length = count;
  while (length > 1) {
    const uint32_t half = length / 2;
    base = entries[base + half - 1].cdf <= u ? base + half : base;
    length -= half;
  }
  return base;
}

// Power heuristic with beta = 2 (Veach 1997, eq. 9.13): the weight of a sample drawn with pdf
// `a` when the other strategy would have drawn it with pdf `b`, a^2 / (a^2 + b^2). Where the
// squares overflow (a density past 1.8e19: a light under 5e-20 sr), the same weight from the
// densities' ratio r <= 1: 1 / (1 + r^2) for the larger, r^2 / (1 + r^2) for the smaller.
TRACER_HD float power_heuristic(float a, float b) {
  const float a2 = a * a, b2 = b * b, sum = a2 + b2;
  if (sum < kInfinity) return sum > 0.0f ? a2 / sum : 0.0f;
  const float r = a >= b ? b / a : a / b, r2 = r * r;
  return a >= b ? 1.0f / (1.0f + r2) : r2 / (1.0f + r2);
}

}  // namespace tracer
