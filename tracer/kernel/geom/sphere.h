// Ray/sphere intersection in the numerically careful form of Haines et al., "Precision
// Improvements for Ray/Sphere Intersection" (Ray Tracing Gems, ch. 7). Needs a unit direction.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

// Smallest root t with tmin < t <= tmax, written to t_out.
TRACER_HD bool intersect_sphere(Vec3 center, float radius, const Ray& ray, float tmin, float tmax, float& t_out) {
  const Vec3 f = ray.origin - center;
  const float b = dot(f, ray.dir);
  const Vec3 l = f - ray.dir * b;  // f minus its projection on the ray
  const float disc = radius * radius - dot(l, l);
  if (disc < 0.0f) return false;
  const float c = dot(f, f) - radius * radius;
  const float q = b > 0.0f ? -b - det_sqrt(disc) : -b + det_sqrt(disc);
  // Both roots with bounds on their rounding error; a root counts only when it is
  // conservatively positive, so a ray leaving the surface does not hit it again.
  float t0 = c / q, t1 = q;
  float e0 = error_gamma(6) * (dot(f, f) + radius * radius) / abs_of(q);
  float e1 = error_gamma(4) * (abs_of(b) + det_sqrt(disc));
  if (t0 > t1) {
    const float s = t0, e = e0;
    t0 = t1, e0 = e1;
    t1 = s, e1 = e;
  }
  if (t0 > tmin && t0 > e0 && t0 <= tmax) {
    t_out = t0;
    return true;
  }
  if (t1 > tmin && t1 > e1 && t1 <= tmax) {
    t_out = t1;
    return true;
  }
  return false;
}

}  // namespace tracer
