#include "scene/scene.h"

namespace tracer {

SceneView Scene::view() const {
  SceneView v{};
  point_view_at(v, *this);
  v.kd_lo = kd_lo;
  v.kd_hi = kd_hi;
  v.kd_pad = kd_pad;
  v.grid = grid;
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
