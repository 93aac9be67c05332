// Axis-aligned bounds of primitives, shared by the acceleration-structure builders.
#pragma once
#include <vector>

#include "kernel/geom/primitive.h"

namespace tracer {

struct Bounds {
  Vec3 lo{kInfinity, kInfinity, kInfinity};
  Vec3 hi{-kInfinity, -kInfinity, -kInfinity};
  void grow(Vec3 p) {
    lo = min_of(lo, p);
    hi = max_of(hi, p);
  }
  void grow(const Bounds& b) {
    lo = min_of(lo, b.lo);
    hi = max_of(hi, b.hi);
  }
  float surface_area() const;
};

// The primitive's box, padded by a few ulps of its coordinates so that it contains every
// point its intersection test can report. Planes are unbounded: an empty box.
Bounds primitive_bounds(const Primitive& p);

// The box of prims[0, count), each as primitive_bounds gives it (planes add nothing): empty
// (lo > hi) when none is bounded.
Bounds bounds_of_primitives(const Primitive* prims, size_t count);

// A bounded primitive as the builders see it.
struct BuildItem {
  Bounds bounds;
  Vec3 centroid;
  uint32_t id;
};

}  // namespace tracer
