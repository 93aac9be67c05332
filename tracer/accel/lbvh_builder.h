// A linear BVH (Karras, "Maximizing Parallelism in the Construction of BVHs, Octrees, and
// k-d Trees", HPG 2012): 30-bit Morton codes of the primitive centroids, sorted with the
// primitive id as tie-break, a binary radix tree whose internal nodes are built
// independently in parallel, then a bottom-up pass of bounding boxes (the second child to
// arrive at a node merges them), with no SAH. The steps are kernel functions
// (kernel/accel/lbvh.h) run here by OpenMP loops (lbvh_build.h) and on the GPU by cuda/lbvh_gpu.cu.
// The tree is laid out in the BvhNode format (children adjacent), so bvh's traversal runs it.
#pragma once
#include "accel/bounds.h"
#include "kernel/accel/bvh_node.h"

namespace tracer {

// Reorders `items` into Morton order (leaf order) and returns the nodes.
std::vector<BvhNode> build_lbvh(std::vector<BuildItem>& items);

}  // namespace tracer
