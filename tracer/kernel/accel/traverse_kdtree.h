// Stackless kd-tree traversal by kd-restart (Foley and Sugerman, "KD-Tree Acceleration
// Structures for a GPU Raytracer", 2005): from the root, descend to the leaf that holds the
// ray at t_min, test its primitives, and restart at the leaf's exit. Primitives sit in every
// leaf their padded bounds overlap; the search stops early only when the best hit lies
// before the leaf's exit minus the pad, so it can never miss a closer hit or a smaller id
// at equal t in a later leaf (docs/determinism.md rule 4).
#pragma once
#include "kernel/accel/primitive_hit.h"

namespace tracer {

template <uint32_t kCode = kTraceAll>
TRACER_HD void traverse_kdtree(const SceneView& scene, const Ray& ray, const RayShear& shear, Hit& best, bool any) {
  if (scene.kd_node_count == 0) return;
  const Vec3 inv = inverse_direction(ray.dir);
  float t_min;
  if (!ray_box(scene.kd_lo, scene.kd_hi, ray.origin, inv, 0.0f, best.t, t_min)) return;
  // The box's exit along the ray, widened like ray_box's far distance.
  float t_end = best.t;
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = (scene.kd_lo[axis] - ray.origin[axis]) * inv[axis];
    const float t1 = (scene.kd_hi[axis] - ray.origin[axis]) * inv[axis];
    const float far = max_of(t0, t1);
    if (far == far) t_end = min_of(t_end, far * (1.0f + 4.0f * 0x1p-24f) + scene.kd_pad);
  }
  while (t_min <= t_end) {
    uint32_t node = 0;
    float t_hi = t_end;
    while (scene.kd_nodes[node].axis != kKdLeaf) {
      const KdNode& n = scene.kd_nodes[node];
      const float o = ray.origin[n.axis];
      const float t_split = (n.split - o) * inv[n.axis];
      const bool below_first = o < n.split || (o == n.split && ray.dir[n.axis] <= 0.0f);
      const uint32_t first = below_first ? n.a : n.b, second = below_first ? n.b : n.a;
      if (!(t_split == t_split) || t_split > t_hi || t_split <= 0.0f) {
        node = first;  // the ray stays on the near side (NaN: it runs inside the split plane)
      } else if (t_split <= t_min) {
        node = second;
      } else {
        node = first;
        t_hi = t_split;
      }
    }
    const KdNode& leaf = scene.kd_nodes[node];
    for (uint32_t i = 0; i < leaf.b; ++i) {
      test_primitive<leaf_trace_code<kCode>()>(scene, scene.kd_prims[leaf.a + i], ray, shear, best);
      if (any && best.prim != kNoHit) return;
    }
    if (best.t < t_hi - scene.kd_pad) return;
    if (t_hi >= t_end) return;
    t_min = t_hi > t_min ? t_hi : float_of_bits(bits_of(t_min) + 1u);  // always advance
  }
}

}  // namespace tracer
