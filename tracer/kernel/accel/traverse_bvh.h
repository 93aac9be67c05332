// Depth-first BVH traversal (bvh and lbvh share the node layout), nearer child first. A
// child is pruned only when it starts strictly beyond the best hit, so a tie at equal t can
// still be won by a smaller id. With `any`, returns at the first hit.
#pragma once
#include "kernel/accel/primitive_hit.h"

namespace tracer {

template <uint32_t kCode = kTraceAll>
TRACER_HD void traverse_bvh(const SceneView& scene, const Ray& ray, const RayShear& shear, Hit& best, bool any) {
  if (scene.bvh_node_count == 0) return;
  const RayBoxQuery q = make_ray_box_query(ray);
  uint32_t stack[64];
  int top = 0;
  uint32_t node = 0;
  float t_enter;
  if (!ray_box(scene.bvh_nodes[0], q, 0.0f, best.t, t_enter)) return;
  for (;;) {
    const BvhNode& n = scene.bvh_nodes[node];
    if (n.count > 0) {
      for (uint32_t i = 0; i < n.count; ++i) {
        test_primitive<leaf_trace_code<kCode>()>(scene, scene.bounded[n.first + i], ray, shear, best);
        if (any && best.prim != kNoHit) return;
      }
    } else {
      float t_left, t_right;
      const BvhNode& l = scene.bvh_nodes[n.first];
      const BvhNode& r = scene.bvh_nodes[n.first + 1];
      const bool hit_l = ray_box(l, q, 0.0f, best.t, t_left);
      const bool hit_r = ray_box(r, q, 0.0f, best.t, t_right);
      if (hit_l && hit_r) {
        const bool left_first = t_left <= t_right;
        stack[top++] = left_first ? n.first + 1 : n.first;
        node = left_first ? n.first : n.first + 1;
        continue;
      }
      if (hit_l || hit_r) {
        node = hit_l ? n.first : n.first + 1;
        continue;
      }
    }
    // Pop the next node that can still hold a hit no farther than the best.
    bool found = false;
    while (top > 0) {
      node = stack[--top];
      const BvhNode& c = scene.bvh_nodes[node];
      if (ray_box(c, q, 0.0f, best.t, t_enter)) {
        found = true;
        break;
      }
    }
    if (!found) return;
  }
}

}  // namespace tracer
