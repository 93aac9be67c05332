// Debug integrators: what the first hit looks like, for tests and for users chasing a bug.
// normals: shading normal (after normal and bump maps) mapped to [0,1]; albedo: the material's base colour;
// depth: distance along the unit camera ray. A miss gives 0.
#pragma once
#include "kernel/shading/surface.h"

namespace tracer {

// The view of `hit`, the closest hit of `ray`.
TRACER_HD Vec3 debug_view(const SceneView& scene, const Ray& ray, const Hit& hit) {
  if (hit.prim == kNoHit) return {0.0f, 0.0f, 0.0f};
  switch (scene.settings.integrator) {
    case IntegratorKind::Normals: {
      Surface s = surface_at(scene, ray, hit);
      material_at(scene, s);  // normal and bump maps bend the shading normal
      return s.ns * 0.5f + Vec3{0.5f, 0.5f, 0.5f};
    }
    case IntegratorKind::Albedo: {
      Surface s = surface_at(scene, ray, hit);
      return material_albedo(material_at(scene, s));
    }
    default: return {hit.t, hit.t, hit.t};
  }
}

}  // namespace tracer
