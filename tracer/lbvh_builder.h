// A linear BVH (Karras, "Maximizing Parallelism in the Construction of BVHs, Octrees, and
// k-d Trees", HPG 2012): 30-bit Morton codes of the primitive centroids, sorted with the
// primitive index as tie-break, a binary radix tree whose internal nodes are built
// independently in parallel (OpenMP), then a bottom-up pass of bounding boxes (the second
// child to arrive at a node merges them), with no SAH. The tree is laid out in the
// BvhNode format (children adjacent), so bvh's traversal runs it unchanged.
#pragma once
#include "bounds.h"

namespace tracer {

// Reorders `items` into Morton order (leaf order) and returns the nodes.
std::vector<BvhNode> build_lbvh(std::vector<BuildItem>& items);

// 10 bits per axis interleaved, x highest, from coordinates in [0, 1].
uint32_t morton_code(Vec3 unit);

}  // namespace tracer
