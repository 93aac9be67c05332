// The stream schedule's ray-state arrays (kernel/integrator/stream.h's StreamStates) for one
// integrator, described once: each scheduler passes its allocator (host memory, device
// memory, or a counter of bytes), so the layout and its size cannot disagree.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/integrator/stream.h"

namespace tracer {

// The queues of state indices a scheduler keeps (render/stream_schedule.h): work and its
// compaction partner, shadow, and Whitted's resume queue.
inline size_t stream_queue_count(const RenderSettings& rs) { return rs.integrator == IntegratorKind::Whitted ? 4 : 3; }

// `allocate(static_cast<T*>(nullptr), count)` returns room for `count` objects of T.
// Arrays an integrator does not use stay null, as do the mirror images' where the scene lists
// no flat mirror.
template <class Allocate>
StreamStates allocate_stream_states(const SceneView& view, size_t width, Allocate&& allocate) {
  const RenderSettings& rs = view.settings;
  const bool path = rs.integrator == IntegratorKind::Path, whitted = rs.integrator == IntegratorKind::Whitted;
  const bool images = path && view.mirror_count > 0;
  const auto array = [&](auto* type, bool used, size_t count = 0) {
    return used ? allocate(type, count == 0 ? width : count) : type;
  };
  StreamStates st{};
  st.pixel = array(static_cast<uint32_t*>(nullptr), true);
  st.sample = array(static_cast<uint32_t*>(nullptr), true);
  st.origin = array(static_cast<Vec3*>(nullptr), true);
  st.dir = array(static_cast<Vec3*>(nullptr), true);
  st.hit = array(static_cast<Hit*>(nullptr), true);
  st.radiance = array(static_cast<Vec3*>(nullptr), true);
  st.next = array(static_cast<uint8_t*>(nullptr), true);
#define TRACER_PATH_ALLOCATE(Type, Stored, name, initial) st.name = array(static_cast<Stored*>(nullptr), path);
  TRACER_PATH_STATE(TRACER_PATH_ALLOCATE)
#undef TRACER_PATH_ALLOCATE
  st.shadow_origin = array(static_cast<Vec3*>(nullptr), path || whitted);
  st.shadow_dir = array(static_cast<Vec3*>(nullptr), path || whitted);
  st.shadow_tmax = array(static_cast<float*>(nullptr), path || whitted);
  st.shadow_emitter = array(static_cast<uint32_t*>(nullptr), path || whitted);
  st.shadow_contribution = array(static_cast<Vec3*>(nullptr), path);
  st.shadow_kinds = array(static_cast<uint8_t*>(nullptr), images);
  st.image = array(static_cast<MirrorQuery*>(nullptr), images);
  st.stack_size = whitted ? whitted_stack_size(rs.max_depth) : 0u;
  st.width = static_cast<uint32_t>(width);
  st.vertex = array(static_cast<WhittedVertex*>(nullptr), whitted);
  st.stack = array(static_cast<WhittedTask*>(nullptr), whitted, width * st.stack_size);
  st.top = array(static_cast<uint32_t*>(nullptr), whitted);
  return st;
}

// Host memory for the state arrays, aligned for any kernel type (each CPU kernel variant has
// its own copy of Hit and the Whitted types, of the same layout).
struct HostStreamArrays {
  std::vector<std::vector<std::max_align_t>> blocks;
  template <class T>
  T* operator()(T*, size_t count) {
    blocks.emplace_back((count * sizeof(T) + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t));
    return reinterpret_cast<T*>(blocks.back().data());
  }
};

// Bytes per sample in flight: the state arrays and the queue entries, and with
// render.stream_order sorted the sort's keys and entries, each in two buffers.
inline size_t stream_bytes_per_state(const SceneView& view) {
  size_t bytes = stream_queue_count(view.settings) * sizeof(uint32_t);
  if (view.settings.stream_order == StreamOrder::Sorted) bytes += 4 * sizeof(uint32_t);
  allocate_stream_states(view, 1, [&](auto* type, size_t count) {
    bytes += count * sizeof(*type);
    return type;
  });
  return bytes;
}

}  // namespace tracer
