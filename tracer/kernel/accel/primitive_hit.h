// A ray's hit and the primitive test every acceleration structure calls
// (kernel/accel/trace.h dispatches the queries). The closest hit is the minimum of
// (t, primitive id) compared lexicographically (docs/determinism.md rule 4).
#pragma once
#include "kernel/accel/alpha_test.h"
#include "kernel/accel/trace_code.h"
#include "kernel/geom/plane.h"
#include "kernel/geom/quad.h"
#include "kernel/geom/sphere.h"
#include "kernel/geom/triangle.h"
#include "kernel/geom/triangle_moller_trumbore.h"
#include "kernel/scene/scene_view.h"

namespace tracer {

struct Hit {
  float t;
  uint32_t prim;  // kNoHit when nothing was hit
  float b1, b2;   // triangle barycentrics of v1, v2 | quad (alpha, beta)
};

// Keeps a hit when (t, id) is below the best so far; t <= best.t is the caller's test.
TRACER_HD void keep_if_closer(Hit& best, float t, uint32_t id, float b1, float b2) {
  if (t < best.t || id < best.prim) best = {t, id, b1, b2};
}

// The code a structure's leaves test with: kCode less the planes, which no structure holds
// (they are unbounded: trace_into tests them before the walk), so no leaf keeps a plane
// test's operands live.
template <uint32_t kCode>
TRACER_HD constexpr uint32_t leaf_trace_code() {
  return kCode & ~uint32_t{kFeaturePlane};
}

// Tests one primitive; keeps it when (t, id) is below the best so far and its material does not
// cut the hit out (alpha_test.h). A shape or triangle
// test outside kCode (trace_code.h) is never in the scenes that run it.
template <uint32_t kCode = kTraceAll>
TRACER_HD void test_primitive(const SceneView& scene, uint32_t id, const Ray& ray, const RayShear& shear, Hit& best) {
  const Primitive& p = scene.primitives[id];
  float t = 0.0f, b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
  bool hit = false;
  switch (p.kind) {  // a shape compiled out of this variant (features.h) is never in its scenes
    case ShapeKind::Sphere:
      if (compiled_in(kFeatureSphere) && traces<kCode>(kFeatureSphere))
        hit = intersect_sphere(p.a, p.radius, ray, 0.0f, best.t, t);
      break;
    case ShapeKind::Plane:
      if (compiled_in(kFeaturePlane) && traces<kCode>(kFeaturePlane))
        hit = intersect_plane(p.a, p.b, ray, 0.0f, best.t, t);
      break;
    case ShapeKind::Triangle:
      if (!compiled_in(kFeatureTriangle) || !traces<kCode>(kFeatureTriangle)) break;
      hit = tests_watertight<kCode>(scene.settings.triangle_test)
                ? intersect_triangle(p.a, p.b, p.c, ray, shear, 0.0f, best.t, t, b0, b1, b2)
                : intersect_triangle_moller_trumbore(p.a, p.b, p.c, ray, 0.0f, best.t, t, b0, b1, b2);
      break;
    case ShapeKind::Quad:
      if (compiled_in(kFeatureQuad) && traces<kCode>(kFeatureQuad))
        hit = intersect_quad(p.a, p.b, p.c, ray, 0.0f, best.t, t, b1, b2);
      break;
  }
  if (hit && alpha_keeps<kCode>(scene, id, ray, t, b1, b2)) keep_if_closer(best, t, id, b1, b2);
}

}  // namespace tracer
