// The runner's CPU scheduler of the stream schedule: render/stream_schedule.h's loop with the
// stages on std::threads (parallel_for) and the compaction and film on one thread, so the
// pack's stream rows and the stream parity case run without a GPU and give the film (and
// each sample) the tracer's OpenMP backend and the GPU's give, bit for bit.
#pragma once
#include <algorithm>
#include <atomic>
#include <utility>
#include <vector>

#include "io/input_error.h"
#include "parity/parallel_for.h"
#include "render/stream_memory.h"
#include "render/stream_order_frame.h"
#include "render/stream_schedule.h"
#include "render/stream_states.h"

namespace tracer {

inline void render_stream_on_cpu(const SceneView& view, const StreamTarget& target, unsigned threads, RayCounts& rays,
                                 StreamStats& stats) {
  struct Backend {
    const SceneView& view;
    const StreamTarget& target;
    unsigned threads;
    StreamStates states;
    std::vector<uint32_t> queues[kStreamQueueCount];
    std::atomic<uint64_t> camera{0}, secondary{0}, shadow{0};

    std::vector<uint32_t>& queue(StreamQueue q) { return queues[static_cast<uint32_t>(q)]; }
    void begin_batch(uint64_t first, size_t count) {
      queue(StreamQueue::Work).resize(count);
      for (size_t i = 0; i < count; ++i) {
        stream_begin_item(target, states, first, i);
        queue(StreamQueue::Work)[i] = static_cast<uint32_t>(i);
      }
    }
    void run(StreamStage stage, StreamQueue q, size_t size) {
      const std::vector<uint32_t>& entries = queue(q);
      parallel_for(size, threads, [&](size_t k) {
        RayCounts c = {0, 0, 0};
        stream_stage(view, stage, states, entries[k], c);
        if (c.camera) camera += c.camera;
        if (c.secondary) secondary += c.secondary;
        if (c.shadow) shadow += c.shadow;
      });
    }
    size_t append(StreamQueue to, size_t to_size, StreamQueue from, size_t from_size) {
      queue(to).resize(to_size);
      queue(to).insert(queue(to).end(), queue(from).begin(), queue(from).begin() + static_cast<ptrdiff_t>(from_size));
      return queue(to).size();
    }
    StreamSplit split(size_t work) {
      for (StreamQueue q : {StreamQueue::Trace, StreamQueue::Shadow, StreamQueue::Resume}) queue(q).clear();
      for (size_t k = 0; k < work; ++k) {
        const uint32_t i = queue(StreamQueue::Work)[k];
        if (states.next[i] & kStreamTrace) queue(StreamQueue::Trace).push_back(i);
        if (states.next[i] & kStreamShadow) queue(StreamQueue::Shadow).push_back(i);
        if (states.next[i] & kStreamResume) queue(StreamQueue::Resume).push_back(i);
      }
      return {queue(StreamQueue::Trace).size(), queue(StreamQueue::Shadow).size(), queue(StreamQueue::Resume).size()};
    }
    void sort(StreamQueue q, size_t size, const RayOrderFrame& frame) {
      const bool shadow = q == StreamQueue::Shadow;
      const Vec3* origin = shadow ? states.shadow_origin : states.origin;
      const Vec3* dir = shadow ? states.shadow_dir : states.dir;
      std::vector<std::pair<uint32_t, uint32_t>> keyed(size);  // (key, state)
      for (size_t k = 0; k < size; ++k) {
        const uint32_t i = queue(q)[k];
        keyed[k] = {ray_order_key(frame, origin[i], dir[i]), i};
      }
      std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (size_t k = 0; k < size; ++k) queue(q)[k] = keyed[k].second;
    }
    void swap(StreamQueue a, StreamQueue b) { queue(a).swap(queue(b)); }
    void end_batch(uint64_t first, size_t count) {
      const uint64_t samples = target.end - target.begin;
      for (uint64_t p = first / samples; p <= (first + count - 1) / samples; ++p)
        stream_end_pixel(target, states, first, count, p);
    }
  };
  const uint64_t total = static_cast<uint64_t>(target.count) * (target.end - target.begin);
  if (const auto why = stream_memory_refusal(view, total)) throw InputError(*why);
  const size_t width = stream_width_for(view.settings, total);
  stats.bytes_per_state = stream_bytes_per_state(view);
  stats.state_bytes = stats.bytes_per_state * width;
  if (width == 0) return;
  HostStreamArrays arrays;
  Backend backend{view, target, threads, allocate_stream_states(view, width, arrays), {}, {}, {}, {}};
  schedule_stream(total, width, backend, stats, stream_order_frame(view));
  rays.camera += backend.camera, rays.secondary += backend.secondary, rays.shadow += backend.shadow;
}

}  // namespace tracer
