#include "scene.h"

namespace tracer {

SceneView Scene::view() const {
  SceneView v{};
  v.primitives = primitives.data();
  v.primitive_count = static_cast<uint32_t>(primitives.size());
  v.triangle_shading = triangle_shading.data();
  v.bounded = bounded.data();
  v.bounded_count = static_cast<uint32_t>(bounded.size());
  v.unbounded = unbounded.data();
  v.unbounded_count = static_cast<uint32_t>(unbounded.size());
  v.bvh_nodes = bvh_nodes.data();
  v.bvh_node_count = static_cast<uint32_t>(bvh_nodes.size());
  v.kd_nodes = kd_nodes.data();
  v.kd_node_count = static_cast<uint32_t>(kd_nodes.size());
  v.kd_prims = kd_prims.data();
  v.kd_lo = kd_lo;
  v.kd_hi = kd_hi;
  v.kd_pad = kd_pad;
  v.grid = grid;
  v.grid_cell_start = grid_cell_start.data();
  v.grid_prims = grid_prims.data();
  v.materials = materials.data();
  v.lights = lights.data();
  v.light_count = static_cast<uint32_t>(lights.size());
  v.textures = textures.data();
  v.texels = texels.data();
  v.light_table = light_table.data();
  v.light_entry_count = static_cast<uint32_t>(light_table.size());
  v.light_of_prim = light_of_prim.data();
  v.sky_cells = sky_cells.data();
  v.sky_cells_per_side = sky_cells_per_side;
  v.sky_light = sky_light;
  v.offset_scale = offset_scale;
  v.background = background;
  v.ambient = ambient;
  v.camera = camera;
  v.settings = settings;
  v.features = features;
  return v;
}

}  // namespace tracer
