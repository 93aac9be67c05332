#include "scene_bundle.h"

#include "options/work_limits.h"

namespace tracer {
namespace {

SceneView without_pointers(SceneView view) {
#define TRACER_NULL_POINTER(Type, name) view.name = nullptr;
  TRACER_SCENE_ARRAYS(TRACER_NULL_POINTER)
#undef TRACER_NULL_POINTER
  return view;
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
  // The render it describes is within the limits render applies to a scene.
  if (const auto v = work_limit_violation(rs.width, rs.height, rs.spp, rs.max_depth))
    throw InputError(path + ": the bundle's render settings: " + v->key + ": " + v->reason);
  if (b.range.begin >= b.range.end || b.range.end > rs.spp)
    throw InputError(path + ": bundle sample range [" + std::to_string(b.range.begin) + ", " +
                     std::to_string(b.range.end) + ") is not inside [0, " + std::to_string(rs.spp) + ")");
  // An adaptive render (render/adaptive_film.h) as the scene loader admits it: whole, with
  // thresholds of 0 (off) or positive and finite, and at least two samples per half decision.
  const auto admissible = [](float v) { return v == 0.0f || (v > 0.0f && v <= 1e6f); };
  if (!admissible(rs.noise_threshold) || !admissible(rs.target_error))
    throw InputError(path + ": the bundle's render settings: noise_threshold " + std::to_string(rs.noise_threshold) +
                     ", target_error " + std::to_string(rs.target_error) + ": expected 0 (off) or from above 0 to 1e6");
  if (adaptive_render(rs) && rs.min_spp < 2)  // above spp is the loader's default for spp < 16: min(min_spp, spp)
    throw InputError(path + ": the bundle's render settings: min_spp " + std::to_string(rs.min_spp) +
                     ": an adaptive render estimates its error from two halves: at least 2");
  if (adaptive_render(rs) && (b.range.begin != 0 || b.range.end != rs.spp))
    throw InputError(path + ": an adaptive render (noise_threshold, target_error) is rendered whole, not samples [" +
                     std::to_string(b.range.begin) + ", " + std::to_string(b.range.end) + ")");
  return b;
}

SceneBundle read_scene_bundle(const std::string& path) { return decode_scene_bundle(read_bundle(path, "scene"), path); }

}  // namespace tracer
