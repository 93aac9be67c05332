// The 8-wide BVH the CPU traverses for `accel: bvh` (kernel/accel/traverse_wide_bvh.h): the
// binary SAH tree collapsed so that one node holds up to 8 child boxes, stored structure of
// arrays so one SIMD step tests all of them, and leaves whose triangles are copied in leaf
// order, 4 to a block, with their vertices inline (no primitive-id indirection).
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

constexpr int kWideBvhWidth = 8;
constexpr int kBlockLanes = 4;

// Child i: its box is lo[axis][i]..hi[axis][i]. Interior: leaf_blocks[i] == 0 and child[i]
// is a node index. Leaf: blocks child[i] .. child[i] + leaf_blocks[i]. An unused slot has
// the inverted box lo = +inf, hi = -inf, which every ray misses.
struct alignas(64) WideBvhNode {
  float lo[3][kWideBvhWidth];
  float hi[3][kWideBvhWidth];
  uint32_t child[kWideBvhWidth];
  uint32_t leaf_blocks[kWideBvhWidth];
};

// Four bounded primitives of one leaf. A lane in `triangle_lanes` is a triangle with its
// vertices v[0..2] inline (the watertight test needs nothing else); a lane in `other_lanes`
// (sphere, quad) is tested through the primitive array; other lanes are empty.
struct alignas(16) TriangleBlock {
  float v[3][3][kBlockLanes];  // [vertex][axis][lane]
  uint32_t id[kBlockLanes];
  uint32_t triangle_lanes;
  uint32_t other_lanes;
  uint32_t pad[2];
};

}  // namespace tracer
