// Depth-first traversal of the 8-wide BVH (kernel/accel/wide_bvh_node.h). All child boxes of a
// node are tested in one step; closest-hit visits the children nearest first, any-hit in
// the node's order and stops at its first hit. An entry popped from the stack is skipped
// only when it starts strictly beyond the best hit, which is what testing its box again
// with tmax = best.t would decide, so a tie at equal t can still be won by a smaller id.
#pragma once
#include "kernel/accel/triangle_block_test.h"

namespace tracer {

// Each interior node pushes at most 7 entries more than it pops, once per level of a tree
// at most 61 levels deep (the binary build stops at depth 60).
constexpr int kWideStackSize = 7 * 61 + 1;

TRACER_HD void traverse_wide_bvh(const SceneView& scene, const Ray& ray, const RayShear& shear, Hit& best, bool any) {
  struct Entry {
    uint32_t child, leaf_blocks;
    float t_enter;
  };
  const WideRayQuery q = make_wide_ray_query(ray, shear);
  Entry stack[kWideStackSize];
  int top = 0;
  stack[top++] = {0u, 0u, 0.0f};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t_enter > best.t) continue;
    if (e.leaf_blocks != 0) {
      for (uint32_t b = e.child; b < e.child + e.leaf_blocks; ++b) {
        test_triangle_block(scene, scene.triangle_blocks[b], q, ray, shear, best);
        if (any && best.prim != kNoHit) return;
      }
      continue;
    }
    const WideBvhNode& n = scene.wide_nodes[e.child];
    float t_enter[kWideBvhWidth];
    const int first = top;
    for (uint32_t hits = wide_box_hits(n, q, best.t, t_enter); hits != 0; hits &= hits - 1) {
      const int i = lowest_set_bit(hits);
      Entry pushed = {n.child[i], n.leaf_blocks[i], t_enter[i]};
      int j = top++;
      if (!any)  // insertion: the stack segment stays sorted far to near, so the nearest pops first
        for (; j > first && stack[j - 1].t_enter < pushed.t_enter; --j) stack[j] = stack[j - 1];
      stack[j] = pushed;
    }
  }
}

}  // namespace tracer
