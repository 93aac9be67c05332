// The Moller-Trumbore ray/triangle test (Moller and Trumbore, "Fast, Minimum Storage
// Ray/Triangle Intersection", JGT 1997): barycentrics by Cramer's rule on the edge vectors,
// no shear and no fallback, so rays through a shared edge or vertex can slip between the
// triangles. Kept as the other side of the watertightness trade (`render.triangle_test`);
// intersect_triangle() in triangle.h is the default.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

TRACER_HD bool intersect_triangle_moller_trumbore(Vec3 v0, Vec3 v1, Vec3 v2, const Ray& ray, float tmin, float tmax,
                                                  float& t_out, float& b0, float& b1, float& b2) {
  const Vec3 e1 = v1 - v0, e2 = v2 - v0;
  const Vec3 p = cross(ray.dir, e2);
  const float det = dot(e1, p);
  if (det == 0.0f) return false;
  const float inv_det = 1.0f / det;
  const Vec3 s = ray.origin - v0;
  const float u = dot(s, p) * inv_det;
  if (u < 0.0f || u > 1.0f) return false;
  const Vec3 q = cross(s, e1);
  const float v = dot(ray.dir, q) * inv_det;
  if (v < 0.0f || u + v > 1.0f) return false;
  const float t = dot(e2, q) * inv_det;
  if (!(t > tmin && t <= tmax)) return false;
  t_out = t;
  b0 = 1.0f - u - v;
  b1 = u;
  b2 = v;
  return true;
}

}  // namespace tracer
