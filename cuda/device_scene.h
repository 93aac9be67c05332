// The scene's flat arrays (every entry of kernel/scene/scene_arrays.h) copied to plain device
// buffers, and a SceneView whose pointers point at them: what a kernel receives by value.
// bvh's 8-wide tree goes to the device only when asked for: it is walked by the
// wide_bvh_triangles trace variant alone (kernel/accel/trace_variants.h), and the binary
// tree, which every GPU kernel walks, gives the same hits.
#pragma once
#include "device_buffer.h"
#include "scene/scene_arrays.h"

namespace tracer {

enum class DeviceBvh { Binary, Wide };

// The tree a view asks for: the 8-wide one where it counts one (a bundle that keeps it).
inline DeviceBvh device_bvh_of(const SceneView& view) {
  return view.wide_node_count != 0 ? DeviceBvh::Wide : DeviceBvh::Binary;
}

class DeviceScene {
 public:
  // `host_view` supplies the scalars (camera, settings, ...); its pointers are replaced.
  DeviceScene(const SceneArrays& arrays, const SceneView& host_view, DeviceBvh bvh = DeviceBvh::Binary)
      :
#define TRACER_UPLOAD(Type, name) name##_(upload(arrays.name, bvh)),
        TRACER_SCENE_ARRAYS(TRACER_UPLOAD)
#undef TRACER_UPLOAD
            view_(host_view) {
    point_view_at(view_, arrays);  // the counts
#define TRACER_POINT_AT_DEVICE(Type, name) view_.name = name##_.get();
    TRACER_SCENE_ARRAYS(TRACER_POINT_AT_DEVICE)
#undef TRACER_POINT_AT_DEVICE
    if (bvh == DeviceBvh::Binary) view_.wide_node_count = 0;
  }

  const SceneView& view() const { return view_; }

  // The device memory the arrays take.
  static size_t bytes(const SceneArrays& arrays, DeviceBvh bvh) {
    const size_t wide =
        arrays.wide_nodes.size() * sizeof(WideBvhNode) + arrays.triangle_blocks.size() * sizeof(TriangleBlock);
    return scene_array_bytes(arrays) - (bvh == DeviceBvh::Binary ? wide : 0);
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
