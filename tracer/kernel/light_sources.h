// Light that does not come from a surface: the background a ray sees when it leaves the
// scene, and point lights' falloff. Shared by the Whitted and path integrators.
#pragma once
#include "scene_view.h"

namespace tracer {

TRACER_HD Vec3 background_radiance(const Background& bg, Vec3 dir) {
  switch (bg.kind) {
    case BackgroundKind::Gradient: {
      const float t = max_of(dir.y, 0.0f);  // horizon at y <= 0, zenith straight up
      return bg.horizon * (1.0f - t) + bg.radiance * t;
    }
    case BackgroundKind::Constant: break;
  }
  return bg.radiance;
}

// Falloff of a point light: physical 1/d^2, or min(1/(kc + kl d + kq d^2), 1).
TRACER_HD float light_falloff(const PointLight& light, float d, float d2) {
  if (!light.has_attenuation) return 1.0f / d2;
  return min_of(1.0f / (light.kc + light.kl * d + light.kq * d2), 1.0f);
}

}  // namespace tracer
