// The GPU walk's layout of a binary BVH (kernel/accel/bvh_pair_node.h): each interior node's
// two children in one record, the leaves' triangles copied out in the order a depth-first walk
// from the root meets them. Deterministic: the result depends only on the tree and the
// triangles.
#pragma once
#include <string>
#include <vector>

#include "kernel/accel/bvh_node.h"
#include "kernel/accel/traverse_bvh_pairs.h"
#include "kernel/geom/primitive.h"

namespace tracer {

struct BvhPairs {
  std::vector<BvhPairNode> nodes;  // nodes[0]: the root's children
  std::vector<PairTriangle> triangles;
};

// Empty when the root is a leaf or a bounded primitive is not a triangle (the binary walk
// serves those). `leaf_order`: the bounded primitives' ids in the order the leaves index.
// InputError naming `source` when a node or leaf points outside the arrays, a node is reached
// twice, or a path holds more interior nodes than the walk's stack (kBvhPairStackSize): a
// bundle's tree is checked here before any walk.
BvhPairs build_bvh_pairs(const std::vector<BvhNode>& binary, const std::vector<uint32_t>& leaf_order,
                         const std::vector<Primitive>& primitives, const std::string& source);

}  // namespace tracer
