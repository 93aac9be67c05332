// A spot light: a point light (point_light.h: intensity I on its axis, its falloff with
// distance) whose intensity falls off with the angle to its axis as KHR_lights_punctual's spot
// does: 1 inside the inner cone, 0 outside the outer cone, and t^2 between them for
// t = (cos - cos_outer) / (cos_inner - cos_outer). A delta light.
#pragma once
#include "kernel/light/point_light.h"

namespace tracer {

// The share of the axial intensity sent along unit direction d (away from the light).
TRACER_HD float spot_factor(const Light& light, Vec3 d) {
  const float c = dot(d, light.direction);
  if (c >= light.cos_inner) return 1.0f;
  if (!(c > light.cos_outer)) return 0.0f;
  const float t = (c - light.cos_outer) / (light.cos_inner - light.cos_outer);
  return t * t;
}

TRACER_HD LightArrival spot_light_arrival(const Light& light, Vec3 p) {
  LightArrival a = point_light_arrival(light, p);
  a.intensity = a.intensity * spot_factor(light, -a.wi);
  return a;
}

// The light sample of spot light `light` chosen with probability pmf, seen from `from`.
TRACER_HD LightSample sample_spot_light(const Light& light, float pmf, Vec3 from) {
  LightSample s = point_light_sample(point_light_arrival(light, from), pmf);
  s.kind = LightKind::Spot;
  s.radiance = s.radiance * spot_factor(light, -s.wi);
  return s;
}

// The power that chooses it in the light table: 2 pi I times the factor's integral over the
// cosine, (1 - cos_inner) + (cos_inner - cos_outer) / 3, with the intensity's luminance.
inline double spot_light_power(const Light& light) {
  const double inner = light.cos_inner, outer = light.cos_outer;
  return 2.0 * kPi * luminance(light.intensity) * ((1.0 - inner) + (inner - outer) / 3.0);
}

}  // namespace tracer
