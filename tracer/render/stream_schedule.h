// The host loop of the stream schedule (kernel/integrator/stream.h, whose stages it names
// without including them), shared by every
// scheduler: the tracer's OpenMP one (render_stream.cpp), the runner's std::thread one
// (cuda/parity/cpu_stream.h) and the GPU's (cuda/gpu_stream.cu). A batch of at most
// `width` pixel samples becomes ray states; each wave runs closest hit over the work queue,
// shades it (with the Whitted states resumed after a shadow ray), runs the shadow queue,
// then compacts the work queue to the states that trace a ray next. The batch's samples go
// into the film in pixel-sample order, so the film is the megakernel's whichever backend ran
// and whatever order its queues hold (a state's radiance depends on its own counters only).
//
// A backend has, for queues named by StreamQueue:
//   void begin_batch(uint64_t first, size_t count)   items [first, first + count) of the target
//                                                    (pixel-major) as states 0..count-1; the
//                                                    Work queue holds them in order
//   void run(StreamStage, StreamQueue, size_t size)  the stage over the queue's first `size` entries
//   size_t append(StreamQueue to, size_t to_size, StreamQueue from, size_t from_size)  new size
//   StreamSplit split(size_t work)                   the first `work` entries of Work into Trace,
//                                                    Shadow and Resume by their next[] bits
//                                                    (kStreamTrace, kStreamShadow, kStreamResume);
//                                                    the order within a queue is the backend's
//   void sort(StreamQueue, size_t size, const RayOrderFrame&)  the queue's first `size` entries
//                                                    ordered by their rays' keys (Trace: origin
//                                                    and dir; Shadow: shadow_origin and shadow_dir),
//                                                    equal keys in the queue's order
//   void swap(StreamQueue, StreamQueue)
//   void end_batch(uint64_t first, size_t count)     the batch's radiance into the film
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>

#include "kernel/geom/ray_order_key.h"
#include "kernel/integrator/stream_stage.h"
#include "kernel/integrator/stream_target.h"
#include "kernel/scene/render_settings.h"

namespace tracer {

// What a stream render measured: queue sizes and the memory of its ray states.
struct StreamStats {
  uint64_t batches = 0;
  uint64_t waves = 0;          // rounds of closest-hit, shade and shadow stages
  uint64_t largest_queue = 0;  // states in the largest closest-hit queue
  uint64_t shadow_rays = 0;    // entries of all shadow queues
  size_t bytes_per_state = 0;  // the ray-state arrays' bytes per sample in flight
  size_t state_bytes = 0;      // all of them, for the stream width
};

// The samples in flight: the width asked for, or all `total` when fewer.
inline size_t stream_width_for(const RenderSettings& rs, uint64_t total) {
  return static_cast<size_t>(total < rs.stream_width ? total : rs.stream_width);
}

enum class StreamQueue : uint32_t { Work, Trace, Shadow, Resume };
constexpr uint32_t kStreamQueueCount = 4;

// The sizes of the queues a split fills.
struct StreamSplit {
  size_t trace, shadow, resume;
};

// `order`: the frame of the keys the trace and shadow queues are sorted by before each wave
// traces them (render.stream_order sorted), or none to trace them in the queues' order.
template <class Backend>
void schedule_stream(uint64_t total, size_t width, Backend& backend, StreamStats& stats,
                     const std::optional<RayOrderFrame>& order,
                     const std::function<void(uint64_t done, uint64_t total)>& progress = {}) {
  for (uint64_t first = 0; first < total; first += width) {
    const size_t count = static_cast<size_t>(std::min<uint64_t>(width, total - first));
    backend.begin_batch(first, count);
    backend.run(StreamStage::Generate, StreamQueue::Work, count);
    size_t work = count, resume = 0;
    while (work > 0 || resume > 0) {
      ++stats.waves;
      stats.largest_queue = std::max<uint64_t>(stats.largest_queue, work);
      backend.run(StreamStage::Closest, StreamQueue::Work, work);
      work = backend.append(StreamQueue::Work, work, StreamQueue::Resume, resume);  // shaded without a new hit
      backend.run(StreamStage::Shade, StreamQueue::Work, work);
      const StreamSplit split = backend.split(work);  // the shadow stage changes no next[] bit
      stats.shadow_rays += split.shadow;
      if (order) {
        backend.sort(StreamQueue::Shadow, split.shadow, *order);
        backend.sort(StreamQueue::Trace, split.trace, *order);
      }
      backend.run(StreamStage::Shadow, StreamQueue::Shadow, split.shadow);
      resume = split.resume, work = split.trace;
      backend.swap(StreamQueue::Work, StreamQueue::Trace);
    }
    backend.end_batch(first, count);
    ++stats.batches;
    if (progress) progress(first + count, total);
  }
}

}  // namespace tracer
