// A point light: intensity I (W/sr, as radiance units times area) at a position, falling off as
// 1/d^2 or, with attenuation, as min(1 / (kc + kl d + kq d^2), 1). A delta light: only next-event
// estimation reaches it (Whitted's local shading, the path tracer's light sample).
#pragma once
#include "kernel/light/light_records.h"
#include "kernel/scene/scene_view.h"
#include "kernel/shading/bsdf_sample.h"

namespace tracer {

// Falloff of a point light: physical 1/d^2, or min(1/(kc + kl d + kq d^2), 1).
TRACER_HD float light_falloff(const Light& light, float d, float d2) {
  if (!light.has_attenuation) return 1.0f / d2;
  return min_of(1.0f / (light.kc + light.kl * d + light.kq * d2), 1.0f);
}

// A declared light as seen from p: the unit direction to it, the distance and its square, and
// what arrives if unoccluded as intensity times falloff (kept apart: Whitted scales the
// intensity by the reflectance before the falloff).
struct LightArrival {
  Vec3 wi;
  float distance, distance2;
  Vec3 intensity;
  float falloff;
};

TRACER_HD LightArrival point_light_arrival(const Light& light, Vec3 p) {
  const Vec3 to_light = light.position - p;
  LightArrival a;
  a.distance2 = dot(to_light, to_light);
  a.distance = det_sqrt(a.distance2);
  a.wi = to_light / a.distance;
  a.intensity = light.intensity;
  a.falloff = light_falloff(light, a.distance, a.distance2);
  return a;
}

// The light sample of a point light chosen with probability pmf that arrives as `a`.
TRACER_HD LightSample point_light_sample(const LightArrival& a, float pmf) {
  LightSample s = {{0.0f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, 0.0f}, 0.0f, LightKind::Point, true, kNoHit, false};
  s.distance = a.distance;
  if (!(s.distance > 0.0f)) return s;
  s.wi = a.wi;
  s.radiance = a.intensity * a.falloff;
  s.pdf = pmf;
  s.valid = true;
  return s;
}

// The light sample of point light `light` chosen with probability pmf, seen from `from`.
TRACER_HD LightSample sample_point_light(const Light& light, float pmf, Vec3 from) {
  return point_light_sample(point_light_arrival(light, from), pmf);
}

// The power that chooses it in the light table: 4 pi times the intensity's luminance.
inline double point_light_power(const Light& light) { return 4.0 * kPi * luminance(light.intensity); }

}  // namespace tracer
