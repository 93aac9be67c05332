// Next-event estimation's shadow ray for a light sample (kernel/light/light.h): what the path
// tracer traces to see whether the sampled light is visible.
#pragma once
#include "kernel/geom/ray_offset.h"
#include "kernel/light/light.h"
#include "kernel/shading/surface.h"

namespace tracer {

// Next-event estimation's shadow ray and the radiance it adds when the light is visible.
struct ShadowQuery {
  Ray ray;
  float tmax;        // any-hit test within (0, tmax] (kInfinity for the sky)
  uint32_t emitter;  // kNoHit: the any-hit test; else the emitter the closest hit must be
  Vec3 contribution;
};

// The shadow ray from the shading point at s to the sampled light: an emitting surface as the
// closest hit along wi; any other light unoccluded up to its distance (the environment: past
// everything).
TRACER_HD ShadowQuery shadow_query(const SceneView& scene, const Surface& s, const LightSample& ls) {
  const Ray ray = {offset_ray_origin(s.p, s.ng, ls.wi, scene.offset_scale), ls.wi};
  if (ls.emitter != kNoHit) return {ray, kInfinity, ls.emitter, {0.0f, 0.0f, 0.0f}};
  if (ls.distance == kInfinity) return {ray, kInfinity, kNoHit, {0.0f, 0.0f, 0.0f}};
  return {ray, length(s.p + ls.wi * ls.distance - ray.origin), kNoHit, {0.0f, 0.0f, 0.0f}};
}

}  // namespace tracer
