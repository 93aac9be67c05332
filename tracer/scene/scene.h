// The host-side scene: owns the flat arrays that kernel code reads through a SceneView.
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "accel/accel_summary.h"
#include "options/render_options.h"
#include "scene/camera_setup.h"
#include "scene/scene_arrays.h"

namespace tracer {

// What loading found, for `tracer info`, --stats and the feature audit; kernel code never reads it.
struct LoadReport {
  std::map<std::string, uint32_t> shape_counts;  // by the scene file's shape type
  uint32_t degenerate_triangles = 0;             // mesh triangles of zero area, left out
  std::set<std::string> used_types;              // "shape:box", "sampler:grid": scene_types.h
  std::set<std::string> input_files;             // meshes and images read, as the scene names them
  AccelSummary accel;                            // the built structure's name, nodes and cells
  size_t accel_bytes = 0;                        // its nodes, cells and index arrays
  double build_seconds = 0.0;                    // its build time
  std::vector<std::string> gltf;                 // a glTF file's contents and what was left out, a line each
};

// The arrays (SceneArrays, listed in kernel/scene/scene_arrays.h) and the view's scalars,
// and the load report.
struct Scene : SceneArrays {
  std::string file;
  Vec3 kd_lo{0, 0, 0}, kd_hi{0, 0, 0};
  float kd_pad = 0.0f;
  GridInfo grid{};
  std::vector<std::string> material_names;
  uint32_t sky_cell_columns = 0, sky_cell_rows = 0;
  uint32_t environment_light = kNoHit;  // the environment's light_table entry
  float offset_scale = 1.0f;            // kernel/geom/ray_offset.h
  Background background{};
  Vec3 ambient{0.0f, 0.0f, 0.0f};
  Camera camera{};
  CameraSpec camera_spec{};  // the look-at description `camera` was made from
  RenderSettings settings{};
  uint32_t features = 0;
  LoadReport report;

  SceneView view() const;
  std::vector<std::string> files_read() const;  // the scene file and every mesh and image it pulled in
};

}  // namespace tracer
