// The texture coordinates of a hit, from the primitive and the hit alone: what surface_at
// (kernel/shading/surface.h) gives a shaded point, and what the cut-out test
// (kernel/accel/alpha_test.h) reads during traversal, computed once here for both. Spheres:
// u = 0.5 + atan2(z, x) / 2 pi, v = 0.5 - asin(y) / pi of the unit normal (docs/textures.md);
// planes: coordinates in frame_around(normal) of the point projected onto the plane; quads:
// their planar coordinates; triangles: their vertices' uvs interpolated, else the barycentrics.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/scene/scene_view.h"
#include "kernel/shading/sampling.h"

namespace tracer {

// A sphere's unit normal at the hit at t.
TRACER_HD Vec3 sphere_hit_normal(const Primitive& p, const Ray& ray, float t) {
  return normalize(ray_at(ray, t) - p.a);
}

// A plane's point at the hit at t, projected onto the plane.
TRACER_HD Vec3 plane_hit_point(const Primitive& p, const Ray& ray, float t) {
  const Vec3 q = ray_at(ray, t);
  return q - p.b * dot(q - p.a, p.b);
}

TRACER_HD void hit_uv(const SceneView& scene, const Primitive& p, const Ray& ray, float t, float b1, float b2, float& u,
                      float& v) {
  switch (p.kind) {
    case ShapeKind::Sphere: {
      const Vec3 n = sphere_hit_normal(p, ray, t);
      u = 0.5f + det_atan2(n.z, n.x) / (2.0f * kPi);
      v = 0.5f - det_asin(clamp_of(n.y, -1.0f, 1.0f)) / kPi;
      return;
    }
    case ShapeKind::Plane: {
      const Vec3 q = plane_hit_point(p, ray, t);
      const Frame f = frame_around(p.b);
      u = dot(q - p.a, f.t);
      v = dot(q - p.a, f.b);
      return;
    }
    case ShapeKind::Quad: break;
    case ShapeKind::Triangle:
      if (p.shading >= 0 && scene.triangle_shading[p.shading].has_uvs) {
        const TriangleShading& sh = scene.triangle_shading[p.shading];
        const float b0 = 1.0f - b1 - b2;
        u = sh.u0 * b0 + sh.u1 * b1 + sh.u2 * b2;
        v = sh.v0 * b0 + sh.v1 * b1 + sh.v2 * b2;
        return;
      }
      break;
  }
  u = b1;
  v = b2;
}

}  // namespace tracer
