// Whitted ray tracing (Whitted 1980) with Blinn-Phong local shading, made iterative: an
// explicit fixed-size stack of weighted rays replaces recursion. How each material kind
// maps onto the model is documented in docs/materials.md and coded in its kind's whitted()
// (kernel/material/, through whitted_response() in bsdf.h).
#pragma once
#include "kernel/geom/ray_offset.h"
#include "kernel/integrator/ray_counts.h"
#include "kernel/light/light.h"
#include "kernel/material/bsdf.h"
#include "kernel/shading/optics.h"
#include "kernel/shading/surface.h"

namespace tracer {

struct WhittedTask {
  Ray ray;
  Vec3 weight;
  uint32_t depth;
};

// A Whitted sample between steps: the vertex being lit. The megakernel keeps it in registers;
// the stream schedule in an array, beside each sample's depth-first stack.
struct WhittedVertex {
  WhittedTask task;  // the ray that found this vertex
  Surface s;
  WhittedResponse w;
  Vec3 n;          // the shading normal facing the incoming ray
  Vec3 local;      // ambient plus the lights lit so far
  uint32_t light;  // the next declared light to consider
  bool front;
  LightArrival arrival;  // from the light before `light`, which faces the surface
  float cos_l;           // between the facing shading normal and arrival.wi
};

// The vertex `hit` of task.ray: adds its emission, or the background on a miss (false).
TRACER_HD_STEP bool whitted_begin(const SceneView& scene, const WhittedTask& task, const Hit& hit, WhittedVertex& v,
                                  Vec3& radiance) {
  if (hit.prim == kNoHit) {
    radiance += task.weight * background_radiance(scene, task.ray.dir);
    return false;
  }
  v.task = task;
  v.s = surface_at(scene, task.ray, hit);
  const Material m = material_at(scene, v.s);
  v.front = dot(task.ray.dir, v.s.ng) < 0.0f;
  v.n = v.front ? v.s.ns : -v.s.ns;
  v.w = whitted_response(m, -dot(task.ray.dir, v.n));
  if (v.front || v.w.two_sided) radiance += task.weight * v.w.emission;
  v.local = v.w.ka * scene.ambient;
  v.light = uses_feature(scene.features, kFeatureDeclaredLights) ? 0u : scene.light_count;
  return true;
}

// Adds the light before v.light (lit, facing the surface, not in shadow): diffuse kd I cos and
// Blinn-Phong specular ks I cos(h, n)^shininess, times the falloff; or, for the microfacet
// kinds, f(wo, l) cos I times the falloff (the material looked up again at the point, its
// shading normal already bent).
TRACER_HD_STEP void whitted_add_light(const SceneView& scene, WhittedVertex& v) {
  const LightArrival& a = v.arrival;
  if (uses_feature(scene.features, kFeatureMicrofacet) && v.w.brdf) {
    const Material m = material_colours_at(scene, v.s);
    const Vec3 f_cos = eval_bsdf(m, -v.task.ray.dir, a.wi, v.n, v.front).f_cos;
    v.local += a.intensity * f_cos * a.falloff;
    return;
  }
  const Vec3 h = normalize(a.wi - v.task.ray.dir);
  const float cos_h = max_of(dot(v.n, h), 0.0f);
  const Vec3 reflected = v.w.kd * v.cos_l + v.w.ks * det_pow(cos_h, v.w.shininess);
  v.local += a.intensity * reflected * a.falloff;
}

// Local shading, one declared light at a time (kernel/light/light.h): ambient plus
// whitted_add_light for each light the surface faces that is not in shadow. Adds the lights that need no shadow ray;
// true with `shadow` set at the first that does (the caller calls whitted_add_light if it is unoccluded, then calls
// again).
TRACER_HD_STEP bool whitted_next_light(const SceneView& scene, WhittedVertex& v, Ray& shadow, float& tmax,
                                       RayCounts& counts) {
  while (v.light < scene.light_count) {
    const Light& light = scene.lights[v.light++];
    v.arrival = light_arrival(light, v.s.p);
    v.cos_l = dot(v.n, v.arrival.wi);
    if (!(v.cos_l > 0.0f)) continue;
    if (scene.settings.effects & kEffectShadows) {
      const Vec3 origin = offset_ray_origin(v.s.p, v.s.ng, v.arrival.wi, scene.offset_scale);
      ++counts.shadow;
      shadow = {origin, v.arrival.wi};
      tmax = light_shadow_distance(light, origin);
      return true;
    }
    whitted_add_light(scene, v);
  }
  return false;
}

// The lit vertex's share of the radiance, and its reflection and refraction rays pushed
// (refraction first, so the reflection is traced first). Entry k of the stack is
// stack[k * stride]: 1 in the megakernel's own array, the batch's width in the stream's.
TRACER_HD_STEP void whitted_finish(const SceneView& scene, const WhittedVertex& v, Vec3& radiance, WhittedTask* stack,
                                   size_t stride, int& top, RayCounts& counts) {
  const WhittedTask& task = v.task;
  radiance += task.weight * v.local;
  if (task.depth >= scene.settings.max_depth) return;

  Vec3 kr = (scene.settings.effects & kEffectReflection) ? v.w.kr : Vec3{0.0f, 0.0f, 0.0f};
  if ((scene.settings.effects & kEffectRefraction) && max_component(v.w.kt) > 0.0f) {
    // Snell's law with relative index eta = n_incident / n_transmitted.
    const float n_in = v.front ? 1.0f : v.w.ior, n_out = v.front ? v.w.ior : 1.0f;
    Vec3 refracted;
    float cos_t;
    if (refract(task.ray.dir, v.n, n_in / n_out, refracted, cos_t)) {
      const float cos_i = -dot(task.ray.dir, v.n);
      const float f = dielectric_reflectance(v.w.fresnel, cos_i, cos_t, n_in, n_out);
      kr += v.w.kt * f;
      const Vec3 weight = task.weight * v.w.kt * (1.0f - f);
      if (max_component(weight) > 0.0f) {
        ++counts.secondary;
        stack[static_cast<size_t>(top++) * stride] = {
            {offset_ray_origin(v.s.p, v.s.ng, refracted, scene.offset_scale), refracted}, weight, task.depth + 1};
      }
    } else {
      kr += v.w.kt;  // total internal reflection
    }
  }
  const Vec3 weight = task.weight * kr;
  if ((scene.settings.effects & kEffectReflection) && max_component(weight) > 0.0f) {
    const Vec3 reflected = reflect(task.ray.dir, v.n);
    ++counts.secondary;
    stack[static_cast<size_t>(top++) * stride] = {
        {offset_ray_origin(v.s.p, v.s.ng, reflected, scene.offset_scale), reflected}, weight, task.depth + 1};
  }
}

// The stack's bound: at most one waiting sibling per level, depth-first.
TRACER_HD uint32_t whitted_stack_size(uint32_t max_depth) { return max_depth + 2u; }

// The megakernel: the whole sample in one call, each shadow ray traced where it is drawn.
// kFeatures without cut-outs traces without the alpha test (trace_code.h).
template <uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD Vec3 whitted_radiance(const SceneView& scene, const Ray& camera_ray, RayCounts& counts) {
  constexpr uint32_t kCode = full_trace_code<kFeatures>();
  WhittedTask stack[kMaxDepth + 2];
  int top = 0;
  stack[top++] = {camera_ray, {1.0f, 1.0f, 1.0f}, 0};
  Vec3 radiance = {0.0f, 0.0f, 0.0f};
  while (top > 0) {
    const WhittedTask task = stack[--top];
    WhittedVertex v;
    if (!whitted_begin(scene, task, trace_closest<kCode>(scene, task.ray, kInfinity), v, radiance)) continue;
    Ray shadow;
    float tmax;
    while (whitted_next_light(scene, v, shadow, tmax, counts))
      if (!trace_any<kCode>(scene, shadow, tmax)) whitted_add_light(scene, v);
    whitted_finish(scene, v, radiance, stack, 1, top, counts);
  }
  return radiance;
}

}  // namespace tracer
