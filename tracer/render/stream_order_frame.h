// The frame of the keys the stream schedule sorts its trace and shadow queues by when
// render.stream_order is sorted (kernel/geom/ray_order_key.h): the origin cells span the box of
// the scene's primitives. Header-only: every scheduler (the tracer's OpenMP one, the runner's,
// the GPU's) takes it from the host's view.
#pragma once
#include <optional>

#include "accel/bounds.h"
#include "kernel/geom/ray_order_key.h"
#include "kernel/scene/scene_view.h"

namespace tracer {

// None when the stream traces its queues in their own order. `host_view` holds host pointers.
inline std::optional<RayOrderFrame> stream_order_frame(const SceneView& host_view) {
  if (host_view.settings.stream_order != StreamOrder::Sorted) return std::nullopt;
  Bounds box = bounds_of_primitives(host_view.primitives, host_view.primitive_count);
  if (!(box.lo.x <= box.hi.x)) box.lo = box.hi = Vec3{0.0f, 0.0f, 0.0f};  // no bounded primitive: one origin cell
  return ray_order_frame(box.lo, box.hi);
}

}  // namespace tracer
