// Which of bvh's trees a GPU upload holds (cuda/device_scene.h) and so which one its kernels
// walk: each gives the same hits.
#pragma once
#include "kernel/accel/trace_variants.h"
#include "kernel/scene/scene_view.h"

namespace tracer {

enum class DeviceBvh {
  Binary,  // the binary tree's nodes (kernel/accel/traverse_bvh.h)
  Pairs,   // and its pair records where every bounded primitive is a triangle (traverse_bvh_pairs.h)
  Wide,    // and the 8-wide tree (traverse_wide_bvh.h)
};

// The tree an upload of a scene with FeatureBit mask `features` asks for, and of `view` (its
// arrays on the host): the 8-wide one where it keeps it (a bundle can), else the binary one,
// with its pair records where the scene's bounded shapes are all triangles (the records hold
// triangles only: for any other scene they would be walked for nothing).
inline DeviceBvh device_bvh_for(uint32_t features, bool wide_tree) {
  if (wide_tree) return DeviceBvh::Wide;
  const uint32_t bounded_shapes = kTraceShapes & ~kFeaturePlane;
  return (features & bounded_shapes) == kFeatureTriangle ? DeviceBvh::Pairs : DeviceBvh::Binary;
}

inline DeviceBvh device_bvh_of(const SceneView& view) {
  return device_bvh_for(view.features, view.wide_node_count != 0);
}

// Whether that upload holds pair records: asked for them, and its binary tree's root is an
// interior node (build_bvh_pairs makes none for a root that is a leaf, or for no tree).
inline bool device_pair_records(const SceneView& view) {
  return device_bvh_of(view) == DeviceBvh::Pairs && view.bvh_node_count != 0 && view.bvh_nodes[0].count == 0;
}

// The trace variant the GPU's stream schedule runs that upload on (kernel/accel/trace_variants.h),
// as `tracer info`, the pack and the runner name it; the device picks it from its own view.
inline int device_trace_variant(const SceneView& view) {
  return trace_variant_of(view.features, view.settings, view.wide_node_count != 0, device_pair_records(view));
}

}  // namespace tracer
