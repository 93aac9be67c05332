// A plain three-component float vector for kernel code. Every operation is one IEEE
// operation per component, so results match bit for bit on the host and on CUDA.
#pragma once
#include "kernel/base/platform.h"

namespace tracer {

struct Vec3 {
  float x, y, z;
  TRACER_HD float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  TRACER_HD float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

TRACER_HD Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
TRACER_HD Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
TRACER_HD Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
TRACER_HD Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
TRACER_HD Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
TRACER_HD Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
TRACER_HD Vec3 operator/(Vec3 a, float s) { return {a.x / s, a.y / s, a.z / s}; }
TRACER_HD Vec3& operator+=(Vec3& a, Vec3 b) { return a = a + b; }
TRACER_HD Vec3& operator*=(Vec3& a, Vec3 b) { return a = a * b; }
TRACER_HD bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

TRACER_HD float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
TRACER_HD Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
TRACER_HD float length(Vec3 a) { return det_sqrt(dot(a, a)); }
TRACER_HD Vec3 normalize(Vec3 a) { return a / length(a); }
TRACER_HD Vec3 min_of(Vec3 a, Vec3 b) { return {min_of(a.x, b.x), min_of(a.y, b.y), min_of(a.z, b.z)}; }
TRACER_HD Vec3 max_of(Vec3 a, Vec3 b) { return {max_of(a.x, b.x), max_of(a.y, b.y), max_of(a.z, b.z)}; }
TRACER_HD float max_component(Vec3 a) { return max_of(a.x, max_of(a.y, a.z)); }
TRACER_HD bool is_finite(Vec3 a) { return is_finite(a.x) && is_finite(a.y) && is_finite(a.z); }

struct Ray {
  Vec3 origin;
  Vec3 dir;
};

TRACER_HD Vec3 ray_at(const Ray& r, float t) { return r.origin + r.dir * t; }

}  // namespace tracer
