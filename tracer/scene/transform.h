// Affine transforms of docs/scene-format.md (translate, scale, rotate, rotate_xyz), composed in
// the order listed and baked into the geometry at load time. Rotations use the
// deterministic sin/cos, so goldens do not depend on the machine's libm.
#pragma once
#include <glm/mat3x3.hpp>

#include "kernel/base/vec3.h"

namespace tracer {

struct Transform {
  glm::mat3 m = glm::mat3(1.0f);  // GLM's column-major: m[column][row]
  Vec3 t = {0, 0, 0};
  bool uniform_scale = true;  // false once a non-uniform scale was applied
  float scale = 1.0f;         // the product of uniform scale factors

  Vec3 point(Vec3 p) const { return vector(p) + t; }
  Vec3 vector(Vec3 v) const;
  Vec3 normal(Vec3 n) const;  // by the inverse transpose, normalised
  bool mirrors() const;       // a negative determinant: the placement turns right-handed frames left

  // this, followed by `next`
  Transform then(const Transform& next) const;
  static Transform translation(Vec3 d);
  static Transform scaling(Vec3 s);
  static Transform rotation(Vec3 axis, float degrees);  // Rodrigues' formula
};

}  // namespace tracer
