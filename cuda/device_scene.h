// The scene's flat arrays (every entry of kernel/scene/scene_arrays.h) copied to plain device
// buffers, and a SceneView whose pointers point at them: what a kernel receives by value.
#pragma once
#include "device_buffer.h"
#include "scene/scene_arrays.h"

namespace tracer {

class DeviceScene {
 public:
  // `host_view` supplies the scalars (camera, settings, ...); its pointers are replaced.
  DeviceScene(const SceneArrays& arrays, const SceneView& host_view)
      :
#define TRACER_UPLOAD(Type, name) name##_(arrays.name),
        TRACER_SCENE_ARRAYS(TRACER_UPLOAD)
#undef TRACER_UPLOAD
            view_(host_view) {
    point_view_at(view_, arrays);  // the counts
#define TRACER_POINT_AT_DEVICE(Type, name) view_.name = name##_.get();
    TRACER_SCENE_ARRAYS(TRACER_POINT_AT_DEVICE)
#undef TRACER_POINT_AT_DEVICE
  }

  const SceneView& view() const { return view_; }

 private:
#define TRACER_DEVICE_ARRAY(Type, name) DeviceBuffer<Type> name##_;
  TRACER_SCENE_ARRAYS(TRACER_DEVICE_ARRAY)
#undef TRACER_DEVICE_ARRAY
  SceneView view_;
};

}  // namespace tracer
