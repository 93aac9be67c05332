// Depth-first traversal of the 8-wide BVH (kernel/accel/wide_bvh_node.h). All child boxes of a
// node are tested in one step; closest-hit visits the children nearest first, any-hit in
// the node's order and stops at its first hit. An entry popped from the stack is skipped
// only when it starts strictly beyond the best hit, which is what testing its box again
// with tmax = best.t would decide, so a tie at equal t can still be won by a smaller id.
#pragma once
#include "kernel/accel/traverse_bvh.h"
#include "kernel/accel/triangle_block_test.h"

namespace tracer {

// Each interior node pushes at most 7 entries more than it pops, once per level of a tree
// at most 61 levels deep (the binary build stops at depth 60): the CPU's full code holds
// any tree the build makes.
constexpr int kWideStackSize = 7 * 61 + 1;
// A trace variant's stack (kernel/accel/trace_variants.h: the GPU's wide-tree kernels), 768
// bytes of local memory. ci/generate-meshes.sh's meshes need 28 (bunny) to 50 (mixed-60k) entries
// (wide_bvh_stack_need, tracer/accel/wide_bvh_builder.h); a deeper tree is walked again
// from the root by the binary traversal, from the hit found so far, so its hits stay the same
// (trace_into, kernel/accel/trace.h: one call site of that walk, not a second one in here).
constexpr int kWideVariantStackSize = 64;

template <uint32_t kCode>
constexpr int wide_stack_size() {
  return is_full_code<kCode>() ? kWideStackSize : kWideVariantStackSize;
}

// Returns false, `best` holding the hit found so far, where the tree is deeper than the stack.
template <uint32_t kCode = kTraceAll, int kStackSize = wide_stack_size<kCode>()>
TRACER_HD bool traverse_wide_bvh(const SceneView& scene, const Ray& ray, const RayShear& shear, Hit& best, bool any) {
  struct Entry {
    uint32_t child, leaf_blocks;
    float t_enter;
  };
  const WideRayQuery q = make_wide_ray_query(ray, shear);
  Entry stack[kStackSize];
  int top = 0;
  Entry e = {0u, 0u, 0.0f};
  for (;;) {
    if (e.leaf_blocks != 0) {
      for (uint32_t b = e.child; b < e.child + e.leaf_blocks; ++b) {
        test_triangle_block<kCode>(scene, scene.triangle_blocks[b], q, ray, shear, best);
        if (any && best.prim != kNoHit) return true;
      }
    } else {
      const WideBvhNode& n = scene.wide_nodes[e.child];
      float t_enter[kWideBvhWidth];
      uint32_t hits = wide_box_hits(n, q, best.t, t_enter);
      if (hits != 0) {
        if (kStackSize < kWideStackSize && top + kWideBvhWidth - 1 > kStackSize) {
          return false;  // a tree deeper than this stack
        }
        int i = lowest_set_bit(hits);
        Entry nearest = {n.child[i], n.leaf_blocks[i], t_enter[i]};
        const int first = top;
        // The nearest child (any-hit: the first) is visited next; the others go on the stack,
        // sorted far to near so that the nearer pop first.
        for (hits &= hits - 1; hits != 0; hits &= hits - 1) {
          i = lowest_set_bit(hits);
          Entry pushed = {n.child[i], n.leaf_blocks[i], t_enter[i]};
          if (!any && pushed.t_enter < nearest.t_enter) {
            const Entry swap = nearest;
            nearest = pushed;
            pushed = swap;
          }
          int j = top++;
          if (!any)
            for (; j > first && stack[j - 1].t_enter < pushed.t_enter; --j) stack[j] = stack[j - 1];
          stack[j] = pushed;
        }
        e = nearest;
        continue;
      }
    }
    do {  // the next entry that starts no farther than the best hit
      if (top == 0) return true;
      e = stack[--top];
    } while (e.t_enter > best.t);
  }
}

}  // namespace tracer
