// Self-intersection avoidance by moving a ray origin off the surface along the geometric
// normal by a few ulps of the position (Waechter and Binder, "A Fast and Robust Method
// for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6). Near the origin, where ulps
// vanish, the paper adds a fixed 2^-16 and switches at 1/32, constants that assume a scene
// about a unit in size; both are multiplied by `scale`, SceneView::offset_scale, a power of
// two that is 1 for scenes of a unit or more and shrinks with smaller ones (found by the
// 1e-4 scale test: a fixed 2^-16 is a third of a sphere of radius 5e-5). Away from the
// origin the paper moves 256 ulps, sized for hit points computed as o + t d; ours are
// re-derived from the primitive to a few ulps (surface.h), so 8 ulps suffice, and 256 ulps
// at 1e5 from the origin would be 2 units (found by the translated-scene test).
#pragma once
#include "kernel/base/float_to_int.h"
#include "kernel/base/vec3.h"

namespace tracer {

TRACER_HD float offset_component(float p, float n, float scale) {
  constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 8.0f;
  if (abs_of(p) < kOrigin * scale) return p + kFloatScale * scale * n;
  const int32_t of_i = trunc_to_int32(kIntScale * n);
  const int32_t delta = p < 0.0f ? -of_i : of_i;
  return float_of_bits(static_cast<uint32_t>(static_cast<int32_t>(bits_of(p)) + delta));
}

// Offset p to the side of the unit geometric normal ng that `toward` points into.
TRACER_HD Vec3 offset_ray_origin(Vec3 p, Vec3 ng, Vec3 toward, float scale) {
  const Vec3 n = dot(toward, ng) < 0.0f ? -ng : ng;
  return {offset_component(p.x, n.x, scale), offset_component(p.y, n.y, scale), offset_component(p.z, n.z, scale)};
}

}  // namespace tracer
