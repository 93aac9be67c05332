// Binned SAH BVH (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies",
// 2007) over the bounded primitives (planes are left out) into the flat node array of
// kernel/accel/bvh_node.h; `leaf_ids` gets their ids in leaf order. Primitives are binned as
// 32-byte SSE boxes on 16 bins per axis, all three axes in one pass; a partition grows both
// children's boxes, so no range is read twice per level. Halves of large ranges are built as
// OpenMP tasks; the nodes and their order do not depend on the thread count. x86-64 only (its
// SSE2 baseline).
#pragma once
#include <span>

#include "accel/bounds.h"
#include "kernel/accel/bvh_node.h"
#include "kernel/geom/primitive.h"

namespace tracer {

// A build of fewer items stays on the calling thread, every phase of it: it takes about 3 ms
// or less alone, and waking idle threads cost about 2 ms on a virtual machine (a cold build of
// the bunny's 3,674 triangles took 4-6x Embree's on 2 threads and 0.9x on one).
constexpr uint32_t kParallelBuildItems = 1u << 14;

std::vector<BvhNode> build_sah_bvh(std::span<const Primitive> primitives, std::vector<uint32_t>& leaf_ids);

}  // namespace tracer
