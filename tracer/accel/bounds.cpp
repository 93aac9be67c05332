#include "accel/bounds.h"

namespace tracer {

float Bounds::surface_area() const {
  if (!(lo.x <= hi.x)) return 0.0f;
  const Vec3 d = hi - lo;
  return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

Bounds primitive_bounds(const Primitive& p) {
  Bounds b;
  switch (p.kind) {
    case ShapeKind::Sphere: {
      const Vec3 r = {p.radius, p.radius, p.radius};
      b.grow(p.a - r);
      b.grow(p.a + r);
      break;
    }
    case ShapeKind::Triangle:
      b.grow(p.a);
      b.grow(p.b);
      b.grow(p.c);
      break;
    case ShapeKind::Quad:
      b.grow(p.a);
      b.grow(p.a + p.b);
      b.grow(p.a + p.c);
      b.grow(p.a + p.b + p.c);
      break;
    case ShapeKind::Plane: return b;  // unbounded: never in the BVH
  }
  // Corners such as a + b + c are rounded: pad by a few ulps of the coordinates so that a
  // box always contains every point its primitive's intersection test can report.
  const float m = max_of(max_component(max_of(b.lo, -b.lo)), max_component(max_of(b.hi, -b.hi)));
  const float pad = m * 0x1p-20f + 0x1p-120f;
  b.lo = b.lo - Vec3{pad, pad, pad};
  b.hi = b.hi + Vec3{pad, pad, pad};
  return b;
}

Bounds bounds_of_primitives(const Primitive* prims, size_t count) {
  Bounds box;
  for (size_t i = 0; i < count; ++i) box.grow(primitive_bounds(prims[i]));
  return box;
}

}  // namespace tracer
