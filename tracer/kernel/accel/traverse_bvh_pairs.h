// The binary BVH walked through its pair records (kernel/accel/bvh_pair_node.h): one record
// gives both children's boxes, so a step is four loads and two box tests, and a leaf's
// triangles are read in place. Nearer child first; the farther one goes on the stack with its
// entry distance and is skipped when popped only when it starts strictly beyond the best hit,
// which is what testing its box again with tmax = best.t would decide (traverse_bvh.h does
// that), so both walks keep the same (t, id) minimum, ties included.
#pragma once
#include "kernel/accel/bvh_pair_node.h"
#include "kernel/accel/traverse_bvh.h"

namespace tracer {

// The interior nodes a root-to-leaf path may hold (the SAH build stops at depth 60, the LBVH's
// 62-bit keys at 62): records are built only for such trees (tracer/accel/bvh_pairs_builder.h),
// and a walk pushes at most one entry per interior node of its path.
constexpr uint32_t kBvhPairStackSize = 64;

// ray_box's slab test with the near and far planes chosen by selects instead of through an
// address, so boxes held in registers stay there: the same operations on the same values.
TRACER_HD bool ray_box_in_registers(const Vec3& lo, const Vec3& hi, const RayBoxQuery& q, float tmax, float& t_enter) {
  float tmin = 0.0f;
  for (int axis = 0; axis < 3; ++axis) {
    const bool negative = q.negative[axis] != 0;
    const float t0 = ((negative ? hi[axis] : lo[axis]) - q.origin[axis]) * q.inv_dir[axis];
    const float t1 = ((negative ? lo[axis] : hi[axis]) - q.origin[axis]) * q.inv_dir[axis] * kSlabWiden;
    tmin = max_of(t0, tmin);  // a NaN t0 or t1 (0 * inf) leaves the bound as it was
    tmax = min_of(t1, tmax);
  }
  t_enter = tmin;
  return tmin <= tmax;
}

// One leaf's triangles from `slot` to the one marked last; false when `any` found a hit.
template <uint32_t kCode>
TRACER_HD bool test_pair_leaf(const SceneView& scene, uint32_t slot, const Ray& ray, const RayShear& shear, Hit& best,
                              bool any) {
  for (;; ++slot) {
    const PairTriangle tri = load_read_only(scene.bvh_pair_triangles + slot);
    float t = 0.0f, b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
    const bool hit = tests_watertight<kCode>(scene.settings.triangle_test)
                         ? intersect_triangle(tri.a, tri.b, tri.c, ray, shear, 0.0f, best.t, t, b0, b1, b2)
                         : intersect_triangle_moller_trumbore(tri.a, tri.b, tri.c, ray, 0.0f, best.t, t, b0, b1, b2);
    if (hit && alpha_keeps<kCode>(scene, tri.id, ray, t, b1, b2)) keep_if_closer(best, t, tri.id, b1, b2);
    if (any && best.prim != kNoHit) return false;
    if (tri.last) return true;
  }
}

template <uint32_t kCode = kTraceAll>
TRACER_HD void traverse_bvh_pairs(const SceneView& scene, const Ray& ray, const RayShear& shear, Hit& best, bool any) {
  struct Entry {
    int32_t ref;
    float t_enter;
  };
  const RayBoxQuery q = make_ray_box_query(ray);
  float t_root;
  if (!ray_box(scene.bvh_nodes[0], q, 0.0f, best.t, t_root)) return;
  Entry stack[kBvhPairStackSize];
  int top = 0;
  int32_t ref = 0;  // the root's record: the root is interior wherever records exist
  for (;;) {
    while (ref >= 0) {
      const BvhPairNode n = load_read_only(scene.bvh_pairs + ref);
      float t0, t1;
      const bool hit0 = ray_box_in_registers(n.lo0, n.hi0, q, best.t, t0);
      const bool hit1 = ray_box_in_registers(n.lo1, n.hi1, q, best.t, t1);
      if (hit0 && hit1) {
        const bool first0 = t0 <= t1;
        stack[top++] = first0 ? Entry{n.ref1, t1} : Entry{n.ref0, t0};
        ref = first0 ? n.ref0 : n.ref1;
      } else if (hit0 || hit1) {
        ref = hit0 ? n.ref0 : n.ref1;
      } else {
        break;
      }
    }
    if (ref < 0 && !test_pair_leaf<kCode>(scene, static_cast<uint32_t>(~ref), ray, shear, best, any)) return;
    do {  // the next entry that starts no farther than the best hit
      if (top == 0) return;
      --top;
    } while (stack[top].t_enter > best.t);
    ref = stack[top].ref;
  }
}

}  // namespace tracer
