// Every light through one dispatch on LightKind (light_records.h): the path tracer's choice of a
// light from the table, a sample of it and the density of reaching it, and Whitted's view of the
// declared lights. A new kind of light is its record's fields, its header beside the others, a
// case in each switch below, and its reader.
#pragma once
#include "kernel/light/directional_light.h"
#include "kernel/light/environment_light.h"
#include "kernel/light/point_light.h"
#include "kernel/light/shape_light.h"
#include "kernel/light/spot_light.h"

namespace tracer {

// The light table entry drawn by u (selection probability LightEntry::pmf).
TRACER_HD uint32_t pick_light(const SceneView& scene, float u) {
  return find_cdf_interval(scene.light_table, scene.light_entry_count, u);
}

// A sample of light entry_index seen from `from`, by (u1, u2) and, for the environment's cell, cell_u.
TRACER_HD LightSample sample_light(const SceneView& scene, uint32_t entry_index, Vec3 from, float u1, float u2,
                                   float cell_u) {
  const LightEntry& entry = scene.light_table[entry_index];
  switch (entry.kind) {
    case LightKind::Point: return sample_point_light(scene.lights[entry.index], entry.pmf, from);
    case LightKind::Spot: return sample_spot_light(scene.lights[entry.index], entry.pmf, from);
    case LightKind::Directional: return sample_directional_light(scene.lights[entry.index], entry.pmf, u1, u2);
    case LightKind::Shape: return sample_shape_light(scene, entry, from, u1, u2);
    case LightKind::Environment: break;
  }
  return sample_environment_light(scene, cell_u, u1, u2);
}

// What a path that leaves the scene along unit dir meets of the declared lights with an
// extent there (suns with an angular size), each weighted against its light sample by the
// power heuristic when `weighted` (NEE on, the ray drawn by a non-specular BSDF of density
// bsdf_pdf). The declared lights are the light table's first entries, in order.
TRACER_HD Vec3 declared_lights_seen(const SceneView& scene, Vec3 dir, bool weighted, float bsdf_pdf) {
  Vec3 sum = {0.0f, 0.0f, 0.0f};
  for (uint32_t i = 0; i < scene.light_count; ++i) {
    const Light& light = scene.lights[i];
    if (light.kind != LightKind::Directional || !in_directional_cone(light, dir)) continue;
    const float w = weighted ? power_heuristic(bsdf_pdf, scene.light_table[i].pmf * directional_cone_pdf(light)) : 1.0f;
    sum += directional_radiance(light) * w;
  }
  return sum;
}

// A declared light (SceneView::lights) as seen from p, for Whitted's local shading: a sun
// with an angular size is drawn as its centre's direction (a hard shadow).
TRACER_HD LightArrival light_arrival(const Light& light, Vec3 p) {
  switch (light.kind) {
    case LightKind::Spot: return spot_light_arrival(light, p);
    case LightKind::Directional: return directional_light_arrival(light);
    default: break;
  }
  return point_light_arrival(light, p);
}

// The power with which a declared light is chosen from the light table; scene_radius bounds
// every primitive but planes (what a sun's light can reach).
inline double light_power(const Light& light, double scene_radius) {
  switch (light.kind) {
    case LightKind::Spot: return spot_light_power(light);
    case LightKind::Directional: return directional_light_power(light, scene_radius);
    default: break;
  }
  return point_light_power(light);
}

// How far a shadow ray from `origin` towards declared light `light` must be clear.
TRACER_HD float light_shadow_distance(const Light& light, Vec3 origin) {
  return light.kind == LightKind::Directional ? kInfinity : length(light.position - origin);
}

}  // namespace tracer
