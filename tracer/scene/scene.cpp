#include "scene/scene.h"

namespace tracer {

std::vector<std::string> Scene::files_read() const {
  std::vector<std::string> files(report.input_files.begin(), report.input_files.end());
  files.push_back(file);
  return files;
}

SceneView Scene::view() const {
  SceneView v{};
  point_view_at(v, *this);
  v.kd_lo = kd_lo;
  v.kd_hi = kd_hi;
  v.kd_pad = kd_pad;
  v.grid = grid;
  v.sky_cell_columns = sky_cell_columns;
  v.sky_cell_rows = sky_cell_rows;
  v.environment_light = environment_light;
  v.offset_scale = offset_scale;
  v.background = background;
  v.ambient = ambient;
  v.camera = camera;
  v.settings = settings;
  v.features = features;
  return v;
}

}  // namespace tracer
