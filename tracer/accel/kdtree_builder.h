// kd-trees over the bounded primitives (kernel/accel/kd_node.h): SAH splits chosen among 32
// binned candidates per axis with the cost model of Wald and Havran ("On building fast
// kd-Trees for Ray Tracing", 2006: traversal 1, intersection 1.5, a 20 % bonus for an
// empty side), or splits at the median centroid along the longest axis (the reference
// design's variant). A primitive goes to every child its padded bounds touch.
#pragma once
#include "accel/bounds.h"

namespace tracer {

enum class KdSplit { Sah, Median };

void build_kdtree(Scene& scene, const std::vector<BuildItem>& items, KdSplit split);

}  // namespace tracer
