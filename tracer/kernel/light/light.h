// Every light through one dispatch on LightKind (light_records.h): the path tracer's choice of a
// light from the table, a sample of it and the density of reaching it, and Whitted's view of the
// declared lights. A new kind of light is its record's fields, its header beside these three, a
// case in each switch below, and its reader.
#pragma once
#include "kernel/light/environment_light.h"
#include "kernel/light/point_light.h"
#include "kernel/light/shape_light.h"

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
    case LightKind::Shape: return sample_shape_light(scene, entry, from, u1, u2);
    case LightKind::Environment: break;
  }
  return sample_environment_light(scene, cell_u, u1, u2);
}

// A declared light (SceneView::lights) as seen from p, for Whitted's local shading. The point is
// the one declared kind today; a declared kind of another shape switches on light.kind here.
TRACER_HD LightArrival light_arrival(const Light& light, Vec3 p) { return point_light_arrival(light, p); }

// The power with which a declared light is chosen from the light table.
inline double light_power(const Light& light) { return point_light_power(light); }

// How far a shadow ray from `origin` towards declared light `light` must be clear.
TRACER_HD float light_shadow_distance(const Light& light, Vec3 origin) { return length(light.position - origin); }

}  // namespace tracer
