// Binned SAH BVH (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies",
// 2007) built on the host into the flat node array of kernel/bvh_node.h.
#pragma once
#include "scene.h"

namespace tracer {

// Fills scene.bounded (primitive ids in leaf order), scene.unbounded (planes) and
// scene.bvh_nodes. The build is sequential and deterministic.
void build_acceleration(Scene& scene);

struct Bounds {
  Vec3 lo{kInfinity, kInfinity, kInfinity};
  Vec3 hi{-kInfinity, -kInfinity, -kInfinity};
  void grow(Vec3 p) { lo = min_of(lo, p); hi = max_of(hi, p); }
  void grow(const Bounds& b) { lo = min_of(lo, b.lo); hi = max_of(hi, b.hi); }
  float surface_area() const;
};

Bounds primitive_bounds(const Primitive& p);

}  // namespace tracer
