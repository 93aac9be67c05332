// Self-intersection avoidance by moving a ray origin off the surface along the geometric
// normal by a few ulps of the position (Waechter and Binder, "A Fast and Robust Method
// for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6), not by a scene-scale epsilon.
#pragma once
#include "vec3.h"

namespace tracer {

TRACER_HD float offset_component(float p, float n) {
  constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
  if (abs_of(p) < kOrigin) return p + kFloatScale * n;
  const int32_t of_i = static_cast<int32_t>(kIntScale * n);
  const int32_t delta = p < 0.0f ? -of_i : of_i;
  return float_of_bits(static_cast<uint32_t>(static_cast<int32_t>(bits_of(p)) + delta));
}

// Offset p to the side of the unit geometric normal ng that `toward` points into.
TRACER_HD Vec3 offset_ray_origin(Vec3 p, Vec3 ng, Vec3 toward) {
  const Vec3 n = dot(toward, ng) < 0.0f ? -ng : ng;
  return {offset_component(p.x, n.x), offset_component(p.y, n.y), offset_component(p.z, n.z)};
}

}  // namespace tracer
