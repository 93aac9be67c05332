// Light that does not come from a surface: the background a ray sees when it leaves the
// scene, and point lights' falloff. Shared by the Whitted and path integrators.
#pragma once
#include "kernel/scene/scene_view.h"

namespace tracer {

// The cube-map face a direction leaves through and its (u, v) there. Each face is seen from
// the centre looking along its axis f with an up vector U (+y for the side faces; +z for +y
// and -z for -y, as a head tilted up or down from looking along -z): right R = f x U,
// u = (1 + d.R / d.f) / 2 to the right, v = (1 + d.U / d.f) / 2 upward.
TRACER_HD uint32_t cube_face(Vec3 d, float& u, float& v) {
  const float ax = abs_of(d.x), ay = abs_of(d.y), az = abs_of(d.z);
  uint32_t face;
  float right, up, along;
  if (ax >= ay && ax >= az) {
    face = d.x >= 0.0f ? 0u : 1u;
    along = ax;
    right = d.x >= 0.0f ? d.z : -d.z;
    up = d.y;
  } else if (ay >= az) {
    face = d.y >= 0.0f ? 2u : 3u;
    along = ay;
    right = d.x;
    up = d.y >= 0.0f ? d.z : -d.z;
  } else {
    face = d.z >= 0.0f ? 4u : 5u;
    along = az;
    right = d.z >= 0.0f ? -d.x : d.x;
    up = d.y;
  }
  u = 0.5f * (1.0f + right / along);
  v = 0.5f * (1.0f + up / along);
  return face;
}

TRACER_HD Vec3 background_radiance(const SceneView& scene, Vec3 dir) {
  const Background& bg = scene.background;
  switch (bg.kind) {
    case BackgroundKind::Gradient: {
      const float t = max_of(dir.y, 0.0f);  // horizon at y <= 0, zenith straight up
      return bg.horizon * (1.0f - t) + bg.radiance * t;
    }
    case BackgroundKind::Cubemap: {
      float u, v;
      const uint32_t face = cube_face(dir, u, v);
      return sample_texture(scene.textures, scene.texels, bg.faces[face], u, v);
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
