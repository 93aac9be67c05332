// Ray/parallelogram intersection: plane hit, then the planar coordinates (alpha, beta) of
// the hit in the basis (u, v) must lie in [0, 1]^2; they are also the quad's uv.
#pragma once
#include "kernel/geom/plane.h"

namespace tracer {

TRACER_HD bool intersect_quad(Vec3 corner, Vec3 u, Vec3 v, const Ray& ray, float tmin, float tmax, float& t_out,
                              float& alpha, float& beta) {
  const Vec3 n = cross(u, v);
  float t = 0.0f;
  if (!intersect_plane(corner, n, ray, tmin, tmax, t)) return false;
  const Vec3 rel = ray_at(ray, t) - corner;
  const float nn = dot(n, n);
  alpha = dot(cross(rel, v), n) / nn;
  beta = dot(cross(u, rel), n) / nn;
  if (!(alpha >= 0.0f && alpha <= 1.0f && beta >= 0.0f && beta <= 1.0f)) return false;
  t_out = t;
  return true;
}

}  // namespace tracer
