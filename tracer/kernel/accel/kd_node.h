// Flat kd-tree node (kernel/accel/traverse_kdtree.h). Interior: axis 0..2, children a (below the
// split) and b (above). Leaf: axis 3, primitives kd_prims[a .. a + b).
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

constexpr uint32_t kKdLeaf = 3;

struct KdNode {
  uint32_t axis;
  uint32_t a, b;
  float split;
};

}  // namespace tracer
