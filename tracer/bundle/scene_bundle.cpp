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
                              const std::string& source) {
  // The 8-wide BVH is the host's layout of bvh_nodes; a bundle's reader walks the binary
  // tree (the same hits), so the bundle leaves it out and stays about half the size.
  SceneBundle bundle{arrays, without_pointers(view), range, source};
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
  return b;
}

SceneBundle read_scene_bundle(const std::string& path) { return decode_scene_bundle(read_bundle(path, "scene"), path); }

}  // namespace tracer
