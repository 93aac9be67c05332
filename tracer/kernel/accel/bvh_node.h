// Flat BVH node and the conservative ray/box slab test.
#pragma once
#include "kernel/base/vec3.h"

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
constexpr float kSlabWiden = 1.0f + 2.0f * error_gamma(3);

TRACER_HD bool ray_box(Vec3 lo, Vec3 hi, Vec3 origin, Vec3 inv_dir, float tmin, float tmax, float& t_enter) {
  for (int axis = 0; axis < 3; ++axis) {
    float t0 = (lo[axis] - origin[axis]) * inv_dir[axis];
    float t1 = (hi[axis] - origin[axis]) * inv_dir[axis];
    if (t0 > t1) {
      const float s = t0;
      t0 = t1;
      t1 = s;
    }
    t1 = t1 * kSlabWiden;
    tmin = max_of(t0, tmin);  // a NaN t0 or t1 (0 * inf) leaves the bound as it was
    tmax = min_of(t1, tmax);
    if (tmin > tmax) return false;
  }
  t_enter = tmin;
  return true;
}

// The same test with the near and far slab planes picked once per ray by the direction's
// sign bits (Williams et al., "An Efficient and Robust Ray-Box Intersection Algorithm",
// 2005) instead of compared per box: the same t values, so the same answers.
struct RayBoxQuery {
  Vec3 origin, inv_dir;
  int negative[3];  // 1 where the direction's sign bit is set (-0 included)
};

TRACER_HD RayBoxQuery make_ray_box_query(const Ray& ray) {
  RayBoxQuery q = {ray.origin, inverse_direction(ray.dir), {0, 0, 0}};
  for (int a = 0; a < 3; ++a) q.negative[a] = static_cast<int>(bits_of(ray.dir[a]) >> 31);
  return q;
}

TRACER_HD bool ray_box(const BvhNode& box, const RayBoxQuery& q, float tmin, float tmax, float& t_enter) {
  const Vec3* bounds[2] = {&box.lo, &box.hi};
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = ((*bounds[q.negative[axis]])[axis] - q.origin[axis]) * q.inv_dir[axis];
    const float t1 = ((*bounds[1 - q.negative[axis]])[axis] - q.origin[axis]) * q.inv_dir[axis] * kSlabWiden;
    tmin = max_of(t0, tmin);  // a NaN t0 or t1 (0 * inf) leaves the bound as it was
    tmax = min_of(t1, tmax);
  }
  t_enter = tmin;
  return tmin <= tmax;
}

}  // namespace tracer
