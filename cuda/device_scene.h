// The scene's flat arrays (every entry of kernel/scene/scene_arrays.h) copied to plain device
// buffers, and a SceneView whose pointers point at them: what a kernel receives by value.
// bvh's binary tree goes to the device as nodes, and, asked for Pairs, also as the pair
// records every binary walk on the device takes (kernel/accel/bvh_pair_node.h), built here
// from the nodes; its 8-wide tree goes only when asked for: it is walked by the
// wide_bvh_triangles trace variant alone (kernel/accel/trace_variants.h). Each gives the same hits.
#pragma once
#include <string>

#include "accel/bvh_pairs_builder.h"
#include "device_buffer.h"
#include "render/device_bvh.h"
#include "scene/scene_arrays.h"

namespace tracer {

class DeviceScene {
 public:
  // `host_view` supplies the scalars (camera, settings, ...); its pointers are replaced.
  // InputError naming `source` when the binary tree points outside its arrays (Pairs).
  DeviceScene(const SceneArrays& arrays, const SceneView& host_view, DeviceBvh bvh = DeviceBvh::Binary,
              const std::string& source = "scene")
      :
#define TRACER_UPLOAD(Type, name) name##_(upload(arrays.name, bvh)),
        TRACER_SCENE_ARRAYS(TRACER_UPLOAD)
#undef TRACER_UPLOAD
            view_(host_view) {
    point_view_at(view_, arrays);  // the counts
#define TRACER_POINT_AT_DEVICE(Type, name) view_.name = name##_.get();
    TRACER_SCENE_ARRAYS(TRACER_POINT_AT_DEVICE)
#undef TRACER_POINT_AT_DEVICE
    if (bvh != DeviceBvh::Wide) view_.wide_node_count = 0;
    view_.bvh_pair_count = 0;       // records come from the nodes here, never from the arrays given
    if (bvh == DeviceBvh::Pairs) {  // none for a tree of other shapes, or no binary tree
      const BvhPairs pairs = build_bvh_pairs(arrays.bvh_nodes, arrays.bounded, arrays.primitives, source);
      bvh_pairs_ = DeviceBuffer<BvhPairNode>(pairs.nodes);
      bvh_pair_triangles_ = DeviceBuffer<PairTriangle>(pairs.triangles);
      view_.bvh_pairs = bvh_pairs_.get();
      view_.bvh_pair_triangles = bvh_pair_triangles_.get();
      view_.bvh_pair_count = static_cast<uint32_t>(pairs.nodes.size());
    }
  }

  const SceneView& view() const { return view_; }

  // The device memory the arrays take.
  static size_t bytes(const SceneArrays& arrays, DeviceBvh bvh) {
    const size_t wide =
        arrays.wide_nodes.size() * sizeof(WideBvhNode) + arrays.triangle_blocks.size() * sizeof(TriangleBlock);
    // at most one record per two nodes and one triangle per bounded primitive
    const size_t pairs = bvh == DeviceBvh::Pairs ? arrays.bvh_nodes.size() / 2 * sizeof(BvhPairNode) +
                                                       arrays.bounded.size() * sizeof(PairTriangle)
                                                 : 0;
    return scene_array_bytes(arrays) - (bvh != DeviceBvh::Wide ? wide : 0) + pairs;
  }

 private:
  template <class T>
  static DeviceBuffer<T> upload(const std::vector<T>& host, DeviceBvh) {
    return DeviceBuffer<T>(host);
  }
  static DeviceBuffer<WideBvhNode> upload(const std::vector<WideBvhNode>& host, DeviceBvh bvh) {
    return bvh == DeviceBvh::Wide ? DeviceBuffer<WideBvhNode>(host) : DeviceBuffer<WideBvhNode>();
  }
  static DeviceBuffer<TriangleBlock> upload(const std::vector<TriangleBlock>& host, DeviceBvh bvh) {
    return bvh == DeviceBvh::Wide ? DeviceBuffer<TriangleBlock>(host) : DeviceBuffer<TriangleBlock>();
  }

#define TRACER_DEVICE_ARRAY(Type, name) DeviceBuffer<Type> name##_;
  TRACER_SCENE_ARRAYS(TRACER_DEVICE_ARRAY)
#undef TRACER_DEVICE_ARRAY
  SceneView view_;
};

}  // namespace tracer
