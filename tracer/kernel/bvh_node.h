// Flat BVH node and the conservative ray/box slab test.
#pragma once
#include "vec3.h"

namespace tracer {

// Interior: count == 0 and the children are nodes `first` and `first + 1`.
// Leaf: primitives prim_index[first .. first + count).
struct BvhNode {
  Vec3 lo;
  uint32_t first;
  Vec3 hi;
  uint32_t count;
};

// 1 / direction per axis (+-inf for a zero component), reused for every box of a ray.
TRACER_HD Vec3 inverse_direction(Vec3 d) { return {1.0f / d.x, 1.0f / d.y, 1.0f / d.z}; }

// Robust slab test (Ize, "Robust BVH Ray Traversal", JCGT 2013): the far distance is
// widened by 1 + 2 gamma(3) so rounding can only admit a box, never reject one that the
// ray touches. NaN from 0 * inf leaves the interval unchanged (conservative).
TRACER_HD bool ray_box(Vec3 lo, Vec3 hi, Vec3 origin, Vec3 inv_dir, float tmin, float tmax,
                       float& t_enter) {
  constexpr float kWiden = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  for (int axis = 0; axis < 3; ++axis) {
    float t0 = (lo[axis] - origin[axis]) * inv_dir[axis];
    float t1 = (hi[axis] - origin[axis]) * inv_dir[axis];
    if (t0 > t1) {
      const float s = t0;
      t0 = t1;
      t1 = s;
    }
    t1 = t1 * kWiden;
    tmin = t0 > tmin ? t0 : tmin;
    tmax = t1 < tmax ? t1 : tmax;
    if (tmin > tmax) return false;
  }
  t_enter = tmin;
  return true;
}

}  // namespace tracer
