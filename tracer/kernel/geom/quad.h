// Ray/parallelogram intersection: plane hit, then the planar coordinates (alpha, beta) of
// the hit in the basis (u, v) must lie in [0, 1]^2; they are also the quad's uv.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

TRACER_HD bool intersect_quad(Vec3 corner, Vec3 u, Vec3 v, const Ray& ray, float tmin, float tmax,
                              float& t_out, float& alpha, float& beta) {
  const Vec3 n = cross(u, v);
  const float denom = dot(ray.dir, n);
  if (denom == 0.0f) return false;
  const Vec3 rel_origin = corner - ray.origin;
  const float t = dot(rel_origin, n) / denom;
  if (!(t > tmin && t <= tmax)) return false;
  // t must exceed the rounding error of the dot product, so a ray leaving the surface
  // cannot hit it again at t ~ 0.
  const Vec3 abs_rel = {abs_of(rel_origin.x), abs_of(rel_origin.y), abs_of(rel_origin.z)};
  const Vec3 abs_n = {abs_of(n.x), abs_of(n.y), abs_of(n.z)};
  if (!(t > error_gamma(5) * dot(abs_rel, abs_n) / abs_of(denom))) return false;
  const Vec3 rel = ray_at(ray, t) - corner;
  const float nn = dot(n, n);
  alpha = dot(cross(rel, v), n) / nn;
  beta = dot(cross(u, rel), n) / nn;
  if (!(alpha >= 0.0f && alpha <= 1.0f && beta >= 0.0f && beta <= 1.0f)) return false;
  t_out = t;
  return true;
}

}  // namespace tracer
