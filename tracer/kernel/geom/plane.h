// Ray/infinite-plane intersection; planes are unbounded and live outside the BVH. Quads
// take their plane hit from here too. `normal` need not be a unit vector.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

TRACER_HD bool intersect_plane(Vec3 point, Vec3 normal, const Ray& ray, float tmin, float tmax, float& t_out) {
  const float denom = dot(ray.dir, normal);
  if (denom == 0.0f) return false;
  const Vec3 rel_origin = point - ray.origin;
  const float t = dot(rel_origin, normal) / denom;
  if (!(t > tmin && t <= tmax)) return false;
  // t must exceed the rounding error of the dot product, so a ray leaving the surface
  // cannot hit it again at t ~ 0.
  const Vec3 abs_rel = {abs_of(rel_origin.x), abs_of(rel_origin.y), abs_of(rel_origin.z)};
  const Vec3 abs_n = {abs_of(normal.x), abs_of(normal.y), abs_of(normal.z)};
  if (!(t > error_gamma(5) * dot(abs_rel, abs_n) / abs_of(denom))) return false;
  t_out = t;
  return true;
}

}  // namespace tracer
