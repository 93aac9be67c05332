// The kernel's three-component float vector is GLM's glm::vec3 (host and CUDA: GLM marks its
// functions __host__ __device__ under nvcc). Its operators are one IEEE operation per
// component, and glm::dot and glm::cross round as the project's own did ((x*x + y*y) + z*z;
// each component a difference of two products), so results match bit for bit on the host and
// on CUDA. Where GLM's formula rounds differently or has other NaN semantics the project keeps
// its own function: length and normalize (GLM's normalize multiplies by inversesqrt, a
// reciprocal and a multiply; ours divides by det_sqrt) and min_of/max_of (the GPU's min/max
// rules, platform.h).
#pragma once
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "kernel/base/platform.h"

namespace tracer {

using Vec3 = glm::vec3;

TRACER_HD float dot(Vec3 a, Vec3 b) { return glm::dot(a, b); }
TRACER_HD Vec3 cross(Vec3 a, Vec3 b) { return glm::cross(a, b); }
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
