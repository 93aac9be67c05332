// Collapses a binary BVH into the 8-wide layout of kernel/accel/wide_bvh_node.h: from each
// node, the interior child with the largest surface area is replaced by its two children
// until the node has 8 (Wald et al., "Getting Rid of Packets", 2008, as in Embree's BVH
// collapse). Each binary leaf becomes a run of TriangleBlocks holding its primitives in
// leaf order, and so does a whole subtree of at most 8 primitives left over after the
// expansion (2 blocks under one box instead of a nearly empty wide node). Deterministic:
// the result depends only on the binary tree.
#pragma once
#include <span>
#include <vector>

#include "kernel/accel/bvh_node.h"
#include "kernel/accel/wide_bvh_node.h"
#include "kernel/geom/primitive.h"

namespace tracer {

struct WideBvh {
  std::vector<WideBvhNode> nodes;
  std::vector<TriangleBlock> blocks;
};

// `leaf_order`: the bounded primitives' ids in the order the binary leaves index.
WideBvh collapse_to_wide_bvh(std::span<const BvhNode> binary, std::span<const uint32_t> leaf_order,
                             std::span<const Primitive> primitives);

// The most entries a traversal's stack holds at once on this tree (kernel/accel/traverse_wide_bvh.h):
// a node pushes at most one entry per child but the one it visits next, so the deepest need
// is the largest sum of (children - 1) over the interior nodes of one root-to-leaf path.
uint32_t wide_bvh_stack_need(std::span<const WideBvhNode> nodes);

}  // namespace tracer
