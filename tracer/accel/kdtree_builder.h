// kd-trees over the bounded primitives (kernel/accel/kd_node.h): SAH splits chosen among 32
// binned candidates per axis with the cost model of Wald and Havran ("On building fast
// kd-Trees for Ray Tracing", 2006: traversal 1, intersection 1.5, a 20 % bonus for an
// empty side), or splits at the median centroid along the longest axis (the reference
// design's variant). A primitive goes to every child its padded bounds touch.
#pragma once
#include "accel/bounds.h"
#include "kernel/accel/kd_node.h"

namespace tracer {

enum class KdSplit { Sah, Median };

// The tree over `items`: nodes, the primitive ids its leaves list, and its padded box.
struct KdTree {
  std::vector<KdNode> nodes;
  std::vector<uint32_t> prims;
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  float pad = 0.0f;  // as GridInfo::pad
};
KdTree build_kdtree(const std::vector<BuildItem>& items, KdSplit split);

}  // namespace tracer
