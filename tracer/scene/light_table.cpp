#include "scene/light_table.h"

#include <algorithm>
#include <cmath>

#include "accel/bounds.h"
#include "kernel/light/light.h"
#include "kernel/material/bsdf.h"
#include "kernel/shading/mirror_images.h"
#include "scene/environment_cells.h"

namespace tracer {
namespace {

// Radius of a sphere around every bounded primitive: the environment's and the suns' light
// reaches the scene through its cross-section.
double scene_radius(const Scene& scene) {
  const Bounds all = bounds_of_primitives(scene.primitives.data(), scene.primitives.size());
  if (!(all.lo.x <= all.hi.x)) return 1.0;
  return 0.5 * length(all.hi - all.lo);
}

}  // namespace

void build_light_table(Scene& scene) {
  scene.light_table.clear();
  scene.light_of_prim.assign(scene.primitives.size(), kNoHit);
  scene.sky_cells.clear();
  scene.sky_cell_columns = scene.sky_cell_rows = 0;
  scene.environment_light = kNoHit;
  std::vector<double> power;
  const double radius = scene_radius(scene);
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {  // first in the table: declared_lights_seen
    scene.light_table.push_back({scene.lights[i].kind, i, 0.0f, 0.0f});
    power.push_back(light_power(scene.lights[i], radius));
  }
  for (uint32_t id = 0; id < scene.primitives.size(); ++id) {
    const Primitive& p = scene.primitives[id];
    const Material& m = scene.materials[p.material];
    if (!emits(m) || p.kind == ShapeKind::Plane || !(luminance(m.radiance) > 0.0f)) continue;
    scene.light_of_prim[id] = static_cast<uint32_t>(scene.light_table.size());
    scene.light_table.push_back({LightKind::Shape, id, 0.0f, 0.0f});
    power.push_back(shape_light_power(p, m));
  }
  if (samples_environment(scene.background.kind) && scene.settings.sky_sampling == Switch::On &&
      scene.settings.integrator == IntegratorKind::Path) {
    const double luminance_integral = build_environment_cells(scene);
    if (luminance_integral > 0.0) {
      scene.environment_light = static_cast<uint32_t>(scene.light_table.size());
      scene.light_table.push_back({LightKind::Environment, 0, 0.0f, 0.0f});
      power.push_back(kPi * radius * radius * luminance_integral);  // flux through the scene's cross-section
    }
  }
  double total = 0.0;
  for (double w : power) total += w;
  double running = 0.0;
  for (size_t i = 0; i < power.size(); ++i) {
    const double pmf = total > 0.0 ? power[i] / total : 1.0 / static_cast<double>(power.size());
    running += pmf;
    scene.light_table[i].pmf = static_cast<float>(pmf);
    scene.light_table[i].cdf = i + 1 == power.size() ? 1.0f : static_cast<float>(running);
  }
}

void build_mirror_list(Scene& scene) {
  scene.mirror_prims.clear();
  const bool shapes_lit = std::any_of(scene.light_table.begin(), scene.light_table.end(),
                                      [](const LightEntry& e) { return e.kind == LightKind::Shape; });
  if (scene.settings.integrator == IntegratorKind::Path && scene.settings.mirror_images == Switch::On &&
      scene.settings.nee == Switch::On && shapes_lit) {
    const SceneView view = scene.view();
    for (uint32_t id = 0; id < scene.primitives.size(); ++id)
      if (is_planar_mirror(view, scene.primitives[id])) scene.mirror_prims.push_back(id);
  }
  if (!scene.mirror_prims.empty()) scene.features |= kFeatureMirrorImages;
}

}  // namespace tracer
