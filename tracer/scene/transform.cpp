#include "scene/transform.h"

#include "kernel/base/detmath.h"

namespace tracer {

Vec3 Transform::vector(Vec3 v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3 Transform::normal(Vec3 n) const {
  // cofactor matrix = det * inverse transpose; dividing by |det| keeps the orientation
  const Vec3 r0 = {m[0][0], m[0][1], m[0][2]}, r1 = {m[1][0], m[1][1], m[1][2]}, r2 = {m[2][0], m[2][1], m[2][2]};
  const Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
  const float det = dot(r0, c0);
  const Vec3 out = c0 * n.x + c1 * n.y + c2 * n.z;
  return normalize(det < 0.0f ? -out : out);
}

Transform Transform::then(const Transform& next) const {
  Transform r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = next.m[i][0] * m[0][j] + next.m[i][1] * m[1][j] + next.m[i][2] * m[2][j];
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
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  r.uniform_scale = s.x == s.y && s.y == s.z;
  r.scale = abs_of(s.x);
  return r;
}

Transform Transform::rotation(Vec3 axis, float degrees) {
  const Vec3 k = normalize(axis);
  const float rad = degrees * (kPi / 180.0f);
  const float c = det_cos(rad), s = det_sin(rad), one_c = 1.0f - c;
  Transform r;
  r.m[0][0] = c + k.x * k.x * one_c;
  r.m[0][1] = k.x * k.y * one_c - k.z * s;
  r.m[0][2] = k.x * k.z * one_c + k.y * s;
  r.m[1][0] = k.y * k.x * one_c + k.z * s;
  r.m[1][1] = c + k.y * k.y * one_c;
  r.m[1][2] = k.y * k.z * one_c - k.x * s;
  r.m[2][0] = k.z * k.x * one_c - k.y * s;
  r.m[2][1] = k.z * k.y * one_c + k.x * s;
  r.m[2][2] = c + k.z * k.z * one_c;
  return r;
}

}  // namespace tracer
