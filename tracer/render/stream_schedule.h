// The host loop of the stream schedule (kernel/integrator/stream.h), shared by every
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
//   void swap(StreamQueue, StreamQueue)
//   void end_batch(uint64_t first, size_t count)     the batch's radiance into the film
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>

#include "kernel/base/film.h"
#include "kernel/integrator/stream.h"

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

// Where a stream render's samples go: samples [begin, end) of pixels[0..count) (indices
// y * width + x; every pixel in order when `pixels` is null, count = width * height), added
// to film[pixel], or by sample parity to even[pixel] and odd[pixel] (adaptive sampling), or
// each item's radiance stored at samples[item] (the parity case of the stages).
struct StreamTarget {
  const uint32_t* pixels;
  size_t count;
  uint32_t begin, end;
  FilmSum* film;
  FilmSum* even;
  FilmSum* odd;
  Vec3* samples = nullptr;
};

// The samples in flight: the width asked for, or all `total` when fewer.
inline size_t stream_width_for(const RenderSettings& rs, uint64_t total) {
  return static_cast<size_t>(total < rs.stream_width ? total : rs.stream_width);
}

// Item first + i of the target as state i. Items are pixel-major: item g is sample
// begin + g % samples of the (g / samples)-th pixel.
TRACER_HD void stream_begin_item(const StreamTarget& target, const StreamStates& st, uint64_t first, size_t i) {
  const uint32_t samples = target.end - target.begin;
  const uint64_t g = first + i;
  const size_t p = static_cast<size_t>(g / samples);
  st.pixel[i] = target.pixels ? target.pixels[p] : static_cast<uint32_t>(p);
  st.sample[i] = target.begin + static_cast<uint32_t>(g % samples);
}

// The batch's samples of its p-th pixel (counted over the target, as items are), in sample
// order, into the film (or the halves, or samples[]): what every backend's end_batch does per pixel.
TRACER_HD void stream_end_pixel(const StreamTarget& target, const StreamStates& st, uint64_t first, size_t count,
                                uint64_t p) {
  const uint64_t samples = target.end - target.begin;
  const uint64_t from = p * samples > first ? p * samples : first;
  const uint64_t to = (p + 1) * samples < first + count ? (p + 1) * samples : first + count;
  for (uint64_t g = from; g < to; ++g) {
    const size_t i = static_cast<size_t>(g - first);
    if (target.samples) {
      target.samples[g] = st.radiance[i];
      continue;
    }
    const uint32_t pixel = st.pixel[i];
    FilmSum& sum =
        target.film ? target.film[pixel] : (st.sample[i] % 2u == 0u ? target.even[pixel] : target.odd[pixel]);
    film_add(sum, st.radiance[i]);
  }
}

enum class StreamQueue : uint32_t { Work, Trace, Shadow, Resume };
constexpr uint32_t kStreamQueueCount = 4;

// The sizes of the queues a split fills.
struct StreamSplit {
  size_t trace, shadow, resume;
};

template <class Backend>
void schedule_stream(uint64_t total, size_t width, Backend& backend, StreamStats& stats,
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
