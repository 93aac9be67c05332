#include "scene/transform.h"

#include <glm/matrix.hpp>

#include "kernel/base/detmath.h"

namespace tracer {

Vec3 Transform::vector(Vec3 v) const { return m * v; }  // each row's products summed left to right

Vec3 Transform::normal(Vec3 n) const {
  // The cofactor matrix, det * M^-T, has the columns c0, c1, c2: the cross products of M's
  // columns, which are det times the rows of M^-1. Dividing its product with n by |det|
  // keeps the orientation when M mirrors (our own, not glm::inverseTranspose, whose division
  // by the determinant rounds each entry).
  const Vec3 a0 = m[0], a1 = m[1], a2 = m[2];
  const Vec3 c0 = cross(a1, a2), c1 = cross(a2, a0), c2 = cross(a0, a1);
  const float det = dot(a0, c0);
  const Vec3 out = c0 * n.x + c1 * n.y + c2 * n.z;
  return normalize(det < 0.0f ? -out : out);
}

bool Transform::mirrors() const { return dot(m[0], cross(m[1], m[2])) < 0.0f; }

Transform Transform::then(const Transform& next) const {
  Transform r;
  r.m = next.m * m;
  r.t = next.point(t);
  r.uniform_scale = uniform_scale && next.uniform_scale;
  r.scale = scale * next.scale;
  return r;
}

Transform Transform::translation(Vec3 d) {
  Transform r;
  r.t = d;
  return r;
}

Transform Transform::scaling(Vec3 s) {
  Transform r;
  r.m = glm::mat3(glm::vec3(s.x, 0.0f, 0.0f), glm::vec3(0.0f, s.y, 0.0f), glm::vec3(0.0f, 0.0f, s.z));
  r.uniform_scale = s.x == s.y && s.y == s.z;
  r.scale = abs_of(s.x);
  return r;
}

Transform Transform::rotation(Vec3 axis, float degrees) {
  const Vec3 k = normalize(axis);
  const float rad = degrees * (kPi / 180.0f);
  const float c = det_cos(rad), s = det_sin(rad), one_c = 1.0f - c;
  // Our own, not glm::rotate: its sin and cos are the machine's libm.
  Transform r;
  const glm::vec3 row0(c + k.x * k.x * one_c, k.x * k.y * one_c - k.z * s, k.x * k.z * one_c + k.y * s);
  const glm::vec3 row1(k.y * k.x * one_c + k.z * s, c + k.y * k.y * one_c, k.y * k.z * one_c - k.x * s);
  const glm::vec3 row2(k.z * k.x * one_c - k.y * s, k.z * k.y * one_c + k.x * s, c + k.z * k.z * one_c);
  r.m = glm::transpose(glm::mat3(row0, row1, row2));  // columns given as rows, then transposed
  return r;
}

}  // namespace tracer
