#include "accel/acceleration.h"

#include "accel/bvh_builder.h"
#include "accel/grid_builder.h"
#include "accel/kdtree_builder.h"
#include "accel/lbvh_builder.h"
#include "scene/scene_types.h"

namespace tracer {

float structure_pad(Vec3 lo, Vec3 hi) {
  const float magnitude = max_of(max_component(max_of(lo, -lo)), max_component(max_of(hi, -hi)));
  return max_of(magnitude, max_component(hi - lo)) * 0x1p-18f + 0x1p-100f;
}

void build_acceleration(Scene& scene) {
  std::vector<BuildItem> items;
  scene.bounded.clear();
  scene.unbounded.clear();
  scene.bvh_nodes.clear();
  for (uint32_t id = 0; id < scene.primitives.size(); ++id) {
    const Primitive& p = scene.primitives[id];
    if (p.kind == ShapeKind::Plane) {
      scene.unbounded.push_back(id);
      continue;
    }
    const Bounds b = primitive_bounds(p);
    items.push_back({b, (b.lo + b.hi) * 0.5f, id});
  }
  switch (scene.settings.accel) {
    case AccelKind::Bvh: scene.bvh_nodes = build_sah_bvh(items); break;
    case AccelKind::Lbvh: scene.bvh_nodes = build_lbvh(items); break;
    case AccelKind::Kdtree: build_kdtree(scene, items, KdSplit::Sah); break;
    case AccelKind::KdtreeMedian: build_kdtree(scene, items, KdSplit::Median); break;
    case AccelKind::Grid: build_grid(scene, items); break;
    case AccelKind::None: break;
  }
  for (const BuildItem& it : items) scene.bounded.push_back(it.id);
}

AccelSummary acceleration_summary(const Scene& s) {
  AccelSummary a;
  a.name = accepted_scene_types().at("accel").at(static_cast<size_t>(s.settings.accel));
  a.nodes = s.bvh_nodes.size() + s.kd_nodes.size();
  if (s.settings.accel == AccelKind::Grid) a.cells = s.grid_cell_start.empty() ? 0 : s.grid_cell_start.size() - 1;
  return a;
}

size_t acceleration_bytes(const Scene& s) {
  return s.bvh_nodes.size() * sizeof(BvhNode) + s.bounded.size() * sizeof(uint32_t) + s.kd_nodes.size() * sizeof(KdNode) +
         (s.kd_prims.size() + s.grid_cell_start.size() + s.grid_prims.size()) * sizeof(uint32_t);
}

}  // namespace tracer
