// The host's copy of the arrays a SceneView points to, one std::vector per entry of
// kernel/scene/scene_arrays.h, and the one function that points a view at them.
#pragma once
#include <cstddef>
#include <vector>

#include "kernel/scene/scene_view.h"

namespace tracer {

struct SceneArrays {
#define TRACER_HOST_VECTOR(Type, name) std::vector<Type> name;
  TRACER_SCENE_ARRAYS(TRACER_HOST_VECTOR)
#undef TRACER_HOST_VECTOR
};

// Sets every array pointer of `view` to `arrays`' data and every count from their sizes.
inline void point_view_at(SceneView& view, const SceneArrays& arrays) {
#define TRACER_POINT_AT(Type, name) view.name = arrays.name.data();
  TRACER_SCENE_ARRAYS(TRACER_POINT_AT)
#undef TRACER_POINT_AT
  view.primitive_count = static_cast<uint32_t>(arrays.primitives.size());
  view.bounded_count = static_cast<uint32_t>(arrays.bounded.size());
  view.unbounded_count = static_cast<uint32_t>(arrays.unbounded.size());
  view.bvh_node_count = static_cast<uint32_t>(arrays.bvh_nodes.size());
  view.bvh_pair_count = static_cast<uint32_t>(arrays.bvh_pairs.size());
  view.wide_node_count = static_cast<uint32_t>(arrays.wide_nodes.size());
  view.kd_node_count = static_cast<uint32_t>(arrays.kd_nodes.size());
  view.light_count = static_cast<uint32_t>(arrays.lights.size());
  view.light_entry_count = static_cast<uint32_t>(arrays.light_table.size());
  view.mirror_count = static_cast<uint32_t>(arrays.mirror_prims.size());
}

// Bytes the arrays take (what a device upload allocates).
inline size_t scene_array_bytes(const SceneArrays& arrays) {
  size_t bytes = 0;
#define TRACER_ADD_BYTES(Type, name) bytes += arrays.name.size() * sizeof(Type);
  TRACER_SCENE_ARRAYS(TRACER_ADD_BYTES)
#undef TRACER_ADD_BYTES
  return bytes;
}

}  // namespace tracer
