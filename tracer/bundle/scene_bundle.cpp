#include "scene_bundle.h"

#include "bundle/bundle_references.h"

#include "kernel/light/environment_light.h"
#include "options/settings_check.h"

namespace tracer {
namespace {

SceneView without_pointers(SceneView view) {
#define TRACER_NULL_POINTER(Type, name) view.name = nullptr;
  TRACER_SCENE_ARRAYS(TRACER_NULL_POINTER)
#undef TRACER_NULL_POINTER
  return view;
}

// What the kernels divide by or index with: the grid's cells (traverse_grid.h), the
// environment's cells (environment_light.h), the declared lights' kinds, then every index
// the arrays hold (bundle_references.h). "" when the view agrees with its arrays.
std::string view_violation(const SceneBundle& b) {
  const SceneView& v = b.scalars;
  if (v.settings.accel == AccelKind::Grid) {  // no grid: n = 0 and no cells; else 1 to 1024 cells an axis
    const bool none = b.arrays.grid_cell_start.empty();
    uint64_t cells = 1;
    for (const uint32_t n : v.grid.n) {
      if (none ? n != 0 : (n < 1 || n > 1024))
        return "grid: " + std::to_string(n) + " cells along an axis (" + (none ? "0: it has no cells)" : "1 to 1024)");
      cells *= n;
    }
    if (!none && cells + 1 != b.arrays.grid_cell_start.size())
      return "grid: " + std::to_string(cells) + " cells, but " + std::to_string(b.arrays.grid_cell_start.size()) +
             " cell starts";
  }
  if (!b.arrays.bvh_pairs.empty() || !b.arrays.bvh_pair_triangles.empty() || v.bvh_pair_count != 0)
    return "bvh_pairs: pair records are built from bvh_nodes at upload; a bundle holds none";
  if (!b.arrays.mirror_prims.empty() &&
      (v.settings.integrator != IntegratorKind::Path || v.settings.mirror_images != Switch::On))
    return "mirror_prims: " + std::to_string(b.arrays.mirror_prims.size()) +
           " planar mirrors, but the render does not sample mirror images";
  if (!b.arrays.mirror_prims.empty() && (v.features & kFeatureMirrorImages) == 0u)
    return "mirror_prims: " + std::to_string(b.arrays.mirror_prims.size()) +
           " planar mirrors, but the features lack mirror-images";
  const BackgroundKind background = v.background.kind;
  if (static_cast<uint32_t>(background) > static_cast<uint32_t>(BackgroundKind::Environment))
    return "background: kind " + std::to_string(static_cast<uint32_t>(background));
  const uint32_t columns = v.sky_cell_columns, rows = v.sky_cell_rows;
  if ((b.arrays.sky_cells.empty()
           ? columns != 0 || rows != 0
           : !samples_environment(background) || columns < 1 || rows < 1 || columns > 4096 || rows > 4096) ||
      environment_cell_count(background, columns, rows) != b.arrays.sky_cells.size())
    return "sky: " + std::to_string(columns) + " x " + std::to_string(rows) + " cells, but " +
           std::to_string(b.arrays.sky_cells.size()) + " cells";
  for (size_t i = 0; i < b.arrays.lights.size(); ++i)
    if (!is_declared_kind(b.arrays.lights[i].kind))
      return "lights[" + std::to_string(i) + "]: kind " +
             std::to_string(static_cast<uint32_t>(b.arrays.lights[i].kind)) + " is not a declared light's";
  // The declared lights lead the light table, in order (the miss of a path weighs a sun by its entry).
  const auto& table = b.arrays.light_table;
  if (!table.empty() && table.size() < b.arrays.lights.size())
    return "light_table: " + std::to_string(table.size()) + " entries for " + std::to_string(b.arrays.lights.size()) +
           " declared lights";
  for (size_t i = 0; i < b.arrays.lights.size() && !table.empty(); ++i)
    if (table[i].kind != b.arrays.lights[i].kind || table[i].index != i)
      return "light_table[" + std::to_string(i) + "]: not declared light " + std::to_string(i);
  return bundle_reference_violation(b.arrays, v);
}

}  // namespace

SceneBundle make_scene_bundle(const SceneArrays& arrays, const SceneView& view, SampleRange range,
                              const std::string& source, bool keep_wide_tree) {
  SceneBundle bundle{arrays, without_pointers(view), range, source};
  if (keep_wide_tree) return bundle;
  bundle.arrays.wide_nodes.clear();
  bundle.arrays.triangle_blocks.clear();
  bundle.scalars.wide_node_count = 0;
  return bundle;
}

BundleFile encode_scene_bundle(const SceneBundle& bundle) {
  BundleFile file;
  file.kind = "scene";
  file.add_one("view", without_pointers(bundle.scalars));
  file.add_one("samples", bundle.range);
  file.add("source", std::vector<char>(bundle.source.begin(), bundle.source.end()));
#define TRACER_ADD_ARRAY(Type, name) file.add(#name, bundle.arrays.name);
  TRACER_SCENE_ARRAYS(TRACER_ADD_ARRAY)
#undef TRACER_ADD_ARRAY
  return file;
}

SceneBundle decode_scene_bundle(const BundleFile& file, const std::string& path) {
  SceneBundle b;
  b.scalars = without_pointers(file.get_one<SceneView>("view", path));
  b.range = file.get_one<SampleRange>("samples", path);
  const std::vector<char> source = file.get<char>("source", path);
  b.source.assign(source.begin(), source.end());
#define TRACER_GET_ARRAY(Type, name) b.arrays.name = file.get<Type>(#name, path);
  TRACER_SCENE_ARRAYS(TRACER_GET_ARRAY)
#undef TRACER_GET_ARRAY
  const RenderSettings& rs = b.scalars.settings;
  // The render it describes is one the scene loader could have made (options/settings_check.h).
  if (const auto v = settings_violation(rs))
    throw InputError(path + ": the bundle's render settings: " + v->key + ": " + v->reason);
  if (const std::string v = view_violation(b); !v.empty()) throw InputError(path + ": the bundle's view: " + v);
  if (b.range.begin >= b.range.end || b.range.end > rs.spp)
    throw InputError(path + ": bundle sample range [" + std::to_string(b.range.begin) + ", " +
                     std::to_string(b.range.end) + ") is not inside [0, " + std::to_string(rs.spp) + ")");
  if (adaptive_render(rs) && (b.range.begin != 0 || b.range.end != rs.spp))
    throw InputError(path + ": an adaptive render (noise_threshold, target_error) is rendered whole, not samples [" +
                     std::to_string(b.range.begin) + ", " + std::to_string(b.range.end) + ")");
  return b;
}

SceneBundle read_scene_bundle(const std::string& path) { return decode_scene_bundle(read_bundle(path, "scene"), path); }

}  // namespace tracer
