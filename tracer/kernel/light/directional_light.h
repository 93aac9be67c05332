// A directional light, the sun: light travelling along one direction with irradiance E at
// normal incidence (W/m^2; glTF's lux), either a delta light (angular size 0) or a uniform disc
// of angular radius theta_max, whose radiance L = E / (pi sin^2 theta_max) gives irradiance
// E cos(theta) on any plane that sees the whole disc. Sampled uniformly in its cone
// (pdf 1 / (2 pi (1 - cos theta_max))); a path that leaves the scene inside the cone meets it.
#pragma once
#include "kernel/light/light_records.h"
#include "kernel/light/point_light.h"
#include "kernel/shading/sampling.h"

namespace tracer {

// The radiance of a sun with an angular size: E / (pi sin^2 theta_max), with
// sin^2 = w (2 - w) for w = 1 - cos theta_max (no cancellation for a small disc).
TRACER_HD Vec3 directional_radiance(const Light& light) {
  const float w = light.one_minus_cos;
  return light.intensity / (kPi * (w * (2.0f - w)));
}

// Solid-angle density of a direction within the sun's cone (selection probability excluded).
TRACER_HD float directional_cone_pdf(const Light& light) { return 1.0f / (2.0f * kPi * light.one_minus_cos); }

// Whether unit direction d, leaving the scene, points into the sun's disc (never for a delta sun).
TRACER_HD bool in_directional_cone(const Light& light, Vec3 d) {
  return light.one_minus_cos > 0.0f && 1.0f + dot(d, light.direction) <= light.one_minus_cos;
}

// Whitted's view: the direction of the disc's centre, no falloff with distance.
TRACER_HD LightArrival directional_light_arrival(const Light& light) {
  return {-light.direction, kInfinity, kInfinity, light.intensity, 1.0f};
}

// The light sample of directional light `light` chosen with probability pmf, by (u1, u2).
TRACER_HD LightSample sample_directional_light(const Light& light, float pmf, float u1, float u2) {
  LightSample s = {-light.direction, kInfinity, light.intensity, pmf, LightKind::Directional, true, kNoHit, true};
  if (light.one_minus_cos > 0.0f) {
    s.wi = frame_around(-light.direction).to_world(sample_cone(light.one_minus_cos, u1, u2));
    s.radiance = directional_radiance(light);
    s.pdf = pmf * directional_cone_pdf(light);
    s.delta = false;
  }
  return s;
}

// The power that chooses it in the light table: what crosses a disc of the scene's radius
// facing it, pi r^2 times the irradiance's luminance.
inline double directional_light_power(const Light& light, double scene_radius) {
  return kPi * scene_radius * scene_radius * luminance(light.intensity);
}

}  // namespace tracer
