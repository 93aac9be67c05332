// Whitted ray tracing (Whitted 1980) with Blinn-Phong local shading, made iterative: an
// explicit fixed-size stack of weighted rays replaces recursion. How each material kind
// maps onto the model is documented in docs/materials.md and coded in whitted_response().
#pragma once
#include "kernel/geom/ray_offset.h"
#include "kernel/integrator/ray_counts.h"
#include "kernel/shading/light_sources.h"
#include "kernel/shading/optics.h"
#include "kernel/shading/surface.h"

namespace tracer {

// The classic model's coefficients for one material.
struct WhittedResponse {
  Vec3 ka, kd, ks;  // ambient, diffuse, specular reflectance
  float shininess;
  Vec3 kr;  // mirror reflection weight
  Vec3 kt;  // transmission weight, split by Fresnel into reflection and refraction
  float ior;
  FresnelKind fresnel;
  Vec3 emission;
  bool two_sided;
};

TRACER_HD WhittedResponse whitted_response(const Material& m) {
  const Vec3 zero = {0.0f, 0.0f, 0.0f};
  WhittedResponse w = {zero, zero, zero, 1.0f, zero, zero, 1.0f, m.fresnel, zero, false};
  switch (m.kind) {
    case MaterialKind::Lambert:
      w.ka = m.albedo;
      w.kd = m.albedo;
      break;
    case MaterialKind::Metal:  // a mirror tinted by albedo; roughness has no meaning here
      w.kr = m.albedo;
      break;
    case MaterialKind::Dielectric:
      w.kt = m.tint;
      w.ior = m.ior;
      break;
    case MaterialKind::Phong:
      w.ka = m.ambient;
      w.kd = m.albedo;
      w.ks = m.specular;
      w.shininess = m.shininess;
      w.kr = Vec3{1.0f, 1.0f, 1.0f} * m.reflectivity;
      w.kt = Vec3{1.0f, 1.0f, 1.0f} * m.transparency;
      w.ior = m.ior;
      break;
    case MaterialKind::Emissive:  // an emitter, Lambertian with its albedo (0 unless given)
      w.ka = m.albedo;
      w.kd = m.albedo;
      w.emission = m.radiance;
      w.two_sided = m.two_sided != 0;
      break;
  }
  return w;
}

// Ambient plus, per point light, diffuse kd I cos and Blinn-Phong specular
// ks I cos(h, n)^shininess, each times the falloff, for lights not in shadow.
TRACER_HD Vec3 whitted_local(const SceneView& scene, const WhittedResponse& w, const Surface& s, Vec3 n, Vec3 view_dir,
                             RayCounts& counts) {
  Vec3 result = w.ka * scene.ambient;
  if (!uses_feature(scene.features, kFeaturePointLight)) return result;
  for (uint32_t i = 0; i < scene.light_count; ++i) {
    const PointLight& light = scene.lights[i];
    const Vec3 to_light = light.position - s.p;
    const float d2 = dot(to_light, to_light);
    const float d = det_sqrt(d2);
    const Vec3 l = to_light / d;
    const float cos_l = dot(n, l);
    if (!(cos_l > 0.0f)) continue;
    if (scene.settings.effects & kEffectShadows) {
      const Vec3 origin = offset_ray_origin(s.p, s.ng, l, scene.offset_scale);
      ++counts.shadow;
      if (trace_any(scene, {origin, l}, length(light.position - origin))) continue;
    }
    const Vec3 h = normalize(l - view_dir);
    const float cos_h = max_of(dot(n, h), 0.0f);
    const Vec3 reflected = w.kd * cos_l + w.ks * det_pow(cos_h, w.shininess);
    result += light.intensity * reflected * light_falloff(light, d, d2);
  }
  return result;
}

struct WhittedTask {
  Ray ray;
  Vec3 weight;
  uint32_t depth;
};

TRACER_HD Vec3 whitted_radiance(const SceneView& scene, const Ray& camera_ray, RayCounts& counts) {
  WhittedTask stack[kMaxDepth + 2];  // depth-first: at most one waiting sibling per level
  int top = 0;
  stack[top++] = {camera_ray, {1.0f, 1.0f, 1.0f}, 0};
  Vec3 radiance = {0.0f, 0.0f, 0.0f};
  while (top > 0) {
    const WhittedTask task = stack[--top];
    const Hit hit = trace_closest(scene, task.ray, kInfinity);
    if (hit.prim == kNoHit) {
      radiance += task.weight * background_radiance(scene, task.ray.dir);
      continue;
    }
    Surface s = surface_at(scene, task.ray, hit);
    const WhittedResponse w = whitted_response(material_at(scene, s));
    const bool front = dot(task.ray.dir, s.ng) < 0.0f;
    const Vec3 n = front ? s.ns : -s.ns;  // shading normal facing the incoming ray
    if (front || w.two_sided) radiance += task.weight * w.emission;
    radiance += task.weight * whitted_local(scene, w, s, n, task.ray.dir, counts);
    if (task.depth >= scene.settings.max_depth) continue;

    Vec3 kr = (scene.settings.effects & kEffectReflection) ? w.kr : Vec3{0.0f, 0.0f, 0.0f};
    if ((scene.settings.effects & kEffectRefraction) && max_component(w.kt) > 0.0f) {
      // Snell's law with relative index eta = n_incident / n_transmitted.
      const float n_in = front ? 1.0f : w.ior, n_out = front ? w.ior : 1.0f;
      Vec3 refracted;
      float cos_t;
      if (refract(task.ray.dir, n, n_in / n_out, refracted, cos_t)) {
        const float cos_i = -dot(task.ray.dir, n);
        const float f = dielectric_reflectance(w.fresnel, cos_i, cos_t, n_in, n_out);
        kr += w.kt * f;
        const Vec3 weight = task.weight * w.kt * (1.0f - f);
        if (max_component(weight) > 0.0f) {
          ++counts.secondary;
          stack[top++] = {
              {offset_ray_origin(s.p, s.ng, refracted, scene.offset_scale), refracted}, weight, task.depth + 1};
        }
      } else {
        kr += w.kt;  // total internal reflection
      }
    }
    const Vec3 weight = task.weight * kr;
    if ((scene.settings.effects & kEffectReflection) && max_component(weight) > 0.0f) {
      const Vec3 reflected = reflect(task.ray.dir, n);
      ++counts.secondary;
      stack[top++] = {{offset_ray_origin(s.p, s.ng, reflected, scene.offset_scale), reflected}, weight, task.depth + 1};
    }
  }
  return radiance;
}

}  // namespace tracer
