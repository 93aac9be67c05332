#include "light_table.h"

#include "kernel/bsdf.h"
#include "kernel/light_sampling.h"

namespace tracer {

void build_light_table(Scene& scene) {
  scene.light_table.clear();
  scene.light_of_prim.assign(scene.primitives.size(), kNoHit);
  std::vector<double> power;
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {
    scene.light_table.push_back({LightKind::Point, i, 0.0f, 0.0f});
    power.push_back(4.0 * kPi * luminance(scene.lights[i].intensity));
  }
  for (uint32_t id = 0; id < scene.primitives.size(); ++id) {
    const Primitive& p = scene.primitives[id];
    const Material& m = scene.materials[p.material];
    if (m.kind != MaterialKind::Emissive || p.kind == ShapeKind::Plane || !(luminance(m.radiance) > 0.0f)) continue;
    scene.light_of_prim[id] = static_cast<uint32_t>(scene.light_table.size());
    scene.light_table.push_back({LightKind::Shape, id, 0.0f, 0.0f});
    power.push_back(kPi * luminance(m.radiance) * primitive_area(p) * (m.two_sided ? 2.0 : 1.0));
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

}  // namespace tracer
