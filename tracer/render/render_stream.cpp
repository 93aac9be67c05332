#include "render/render_stream.h"

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "render/ray_order_sort.h"
#include "render/stream_memory.h"
#include "render/stream_order_frame.h"
#include "render/stream_schedule.h"
#include "render/stream_states.h"

namespace tracer {
namespace {

constexpr size_t kChunk = 256;  // queue entries per work item of a stage

// Runs `stage` over queue[0, size) on all threads.
void run_stage(const CpuKernelVariant& variant, const SceneView& view, StreamStage stage, const StreamStates& states,
               const std::vector<uint32_t>& queue, size_t size, int threads, RayCounts& counts) {
  const int64_t chunks = static_cast<int64_t>((size + kChunk - 1) / kChunk);
  uint64_t camera = 0, secondary = 0, shadow = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(+ : camera, secondary, shadow)
  for (int64_t c = 0; c < chunks; ++c) {
    const size_t first = static_cast<size_t>(c) * kChunk;
    RayCounts local{};
    variant.stream_stage(view, static_cast<uint32_t>(stage), &states, queue.data(), first,
                         std::min(first + kChunk, size), local);
    camera += local.camera, secondary += local.secondary, shadow += local.shadow;
  }
  counts.camera += camera, counts.secondary += secondary, counts.shadow += shadow;
}

// in[0, size) split by next[] bits: the entries with kStreamTrace into out[0], kStreamShadow
// into out[1], kStreamResume into out[2] (null where no state resumes), each in order. One
// pass: each thread counts its slice's matches, then writes them after those of the slices
// before it.
void split_queue(const std::vector<uint32_t>& in, size_t size, const uint8_t* next, std::vector<uint32_t>* out[3],
                 int threads) {
  constexpr uint8_t kBits[3] = {kStreamTrace, kStreamShadow, kStreamResume};
  const int queues = out[2] ? 3 : 2;
  std::vector<size_t> offsets(3 * (static_cast<size_t>(threads) + 1), 0);  // per queue, per thread + 1
  for (int q = 0; q < queues; ++q) out[q]->resize(size);
#pragma omp parallel num_threads(threads)
  {
    const size_t t = static_cast<size_t>(omp_get_thread_num()), n = static_cast<size_t>(omp_get_num_threads());
    const size_t begin = size * t / n, end = size * (t + 1) / n;
    size_t* const at[3] = {&offsets[0], &offsets[n + 1], &offsets[2 * (n + 1)]};
    size_t matches[3] = {0, 0, 0};  // local: the offsets of neighbouring threads share cache lines
    for (size_t k = begin; k < end; ++k)
      for (int q = 0; q < queues; ++q) matches[q] += (next[in[k]] & kBits[q]) ? 1 : 0;
    for (int q = 0; q < queues; ++q) at[q][t + 1] = matches[q];
#pragma omp barrier
#pragma omp single
    for (int q = 0; q < queues; ++q)
      for (size_t j = 1; j <= n; ++j) at[q][j] += at[q][j - 1];
    size_t write[3] = {at[0][t], at[1][t], at[2][t]};
    for (size_t k = begin; k < end; ++k)
      for (int q = 0; q < queues; ++q)
        if (next[in[k]] & kBits[q]) (*out[q])[write[q]++] = in[k];
#pragma omp barrier
#pragma omp single
    for (int q = 0; q < queues; ++q) out[q]->resize(at[q][n]);
  }
}

// The OpenMP backend of schedule_stream (render/stream_schedule.h).
struct OpenMpStream {
  const SceneView& view;
  const CpuKernelVariant& variant;
  const StreamTarget& target;
  int threads;
  RayCounts& counts;
  StreamStates states;
  std::vector<uint32_t> queues[kStreamQueueCount];
  std::optional<CpuRaySorter> sorter;  // with render.stream_order sorted

  std::vector<uint32_t>& queue(StreamQueue q) { return queues[static_cast<uint32_t>(q)]; }

  void begin_batch(uint64_t first, size_t count) {
    std::vector<uint32_t>& work = queue(StreamQueue::Work);
    work.resize(count);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (size_t i = 0; i < count; ++i) {
      stream_begin_item(target, states, first, i);
      work[i] = static_cast<uint32_t>(i);
    }
  }

  void run(StreamStage stage, StreamQueue q, size_t size) {
    run_stage(variant, view, stage, states, queue(q), size, threads, counts);
  }

  size_t append(StreamQueue to, size_t to_size, StreamQueue from, size_t from_size) {
    std::vector<uint32_t>& t = queue(to);
    t.resize(to_size);
    t.insert(t.end(), queue(from).begin(), queue(from).begin() + static_cast<ptrdiff_t>(from_size));
    return t.size();
  }

  // Stable: each queue keeps the work queue's order.
  StreamSplit split(size_t work) {
    const bool whitted = view.settings.integrator == IntegratorKind::Whitted;  // only a Whitted vertex resumes
    std::vector<uint32_t>* out[3] = {&queue(StreamQueue::Trace), &queue(StreamQueue::Shadow),
                                     whitted ? &queue(StreamQueue::Resume) : nullptr};
    split_queue(queue(StreamQueue::Work), work, states.next, out, threads);
    return {out[0]->size(), out[1]->size(), whitted ? out[2]->size() : 0};
  }

  void sort(StreamQueue q, size_t size, const RayOrderFrame& frame) {
    const bool shadow = q == StreamQueue::Shadow;
    sorter->sort_queue(queue(q).data(), size, shadow ? states.shadow_origin : states.origin,
                       shadow ? states.shadow_dir : states.dir, frame, threads);
  }

  void swap(StreamQueue a, StreamQueue b) { queue(a).swap(queue(b)); }

  // Into the film in pixel-sample order, a pixel per thread.
  void end_batch(uint64_t first, size_t count) {
    const uint32_t samples = target.end - target.begin;
    const uint64_t first_pixel = first / samples, last_pixel = (first + count - 1) / samples;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t p = static_cast<int64_t>(first_pixel); p <= static_cast<int64_t>(last_pixel); ++p)
      stream_end_pixel(target, states, first, count, static_cast<uint64_t>(p));
  }
};

}  // namespace

void render_stream(const SceneView& view, const CpuKernelVariant& variant, const StreamTarget& target, int threads,
                   RayCounts& counts, StreamStats& stats,
                   const std::function<void(uint64_t done, uint64_t total)>& progress) {
  const uint64_t total = static_cast<uint64_t>(target.count) * (target.end - target.begin);
  const size_t width = stream_width_for(view.settings, total);
  stats.bytes_per_state = stream_bytes_per_state(view);
  const size_t state_bytes = stats.bytes_per_state * width;
  stats.state_bytes = std::max(stats.state_bytes, state_bytes);  // the largest of an adaptive render's passes
  if (width == 0) return;
  if (const auto why = stream_memory_refusal(view, total)) throw InputError(*why);
  const auto refuse = [&] { return InputError(stream_width_refusal(view, total, "cannot be allocated")); };
  HostStreamArrays arrays;
  OpenMpStream backend{view, variant, target, threads, counts, {}, {}, {}};
  const std::optional<RayOrderFrame> order = stream_order_frame(view);
  try {
    backend.states = allocate_stream_states(view, width, arrays);
    for (uint32_t q = 0; q < stream_queue_count(view.settings); ++q) backend.queues[q].reserve(width);
    if (order) backend.sorter.emplace(width);
  } catch (const std::bad_alloc&) {
    throw refuse();
  } catch (const std::length_error&) {
    throw refuse();
  }
  schedule_stream(total, width, backend, stats, order, progress);
}

}  // namespace tracer
