#include "render/render_stream.h"

#include <omp.h>

#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "kernel/integrator/stream.h"

namespace tracer {
namespace {

constexpr size_t kChunk = 256;  // queue entries per work item of a stage

// Storage for `count` objects of a kernel type only the kernel variant reads and writes
// (each variant has its own copy of Hit and the Whitted types, of the same layout).
template <class T>
struct KernelArray {
  std::vector<std::max_align_t> bytes;
  void resize(size_t count) {
    bytes.resize((count * sizeof(T) + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t));
  }
  T* data() { return bytes.empty() ? nullptr : reinterpret_cast<T*>(bytes.data()); }
};

// The arrays behind StreamStates, sized for `width` states of one integrator.
struct StreamArrays {
  std::vector<uint32_t> pixel, sample, depth, shadow_emitter, top;
  std::vector<Vec3> origin, dir, radiance, throughput, from, shadow_origin, shadow_dir, shadow_contribution;
  KernelArray<Hit> hit;
  std::vector<float> bsdf_pdf, shadow_tmax;
  std::vector<uint8_t> next, specular;
  KernelArray<WhittedVertex> vertex;
  KernelArray<WhittedTask> stack;
  uint32_t stack_size = 0;

  StreamArrays(const SceneView& view, size_t width) {
    const IntegratorKind integrator = view.settings.integrator;
    const bool path = integrator == IntegratorKind::Path, whitted = integrator == IntegratorKind::Whitted;
    for (auto* a : {&pixel, &sample}) a->resize(width);
    for (auto* a : {&origin, &dir, &radiance}) a->resize(width);
    hit.resize(width);
    next.resize(width);
    if (path) {
      for (auto* a : {&throughput, &from, &shadow_contribution}) a->resize(width);
      bsdf_pdf.resize(width);
      depth.resize(width);
      specular.resize(width);
    }
    if (path || whitted) {
      for (auto* a : {&shadow_origin, &shadow_dir}) a->resize(width);
      shadow_tmax.resize(width);
      shadow_emitter.resize(width);
    }
    if (whitted) {
      stack_size = whitted_stack_size(view.settings.max_depth);
      vertex.resize(width);
      stack.resize(width * stack_size);
      top.resize(width);
    }
  }

  StreamStates states() {
    return {pixel.data(),
            sample.data(),
            origin.data(),
            dir.data(),
            hit.data(),
            radiance.data(),
            next.data(),
            throughput.data(),
            from.data(),
            bsdf_pdf.data(),
            depth.data(),
            specular.data(),
            shadow_origin.data(),
            shadow_dir.data(),
            shadow_tmax.data(),
            shadow_emitter.data(),
            shadow_contribution.data(),
            vertex.data(),
            stack.data(),
            top.data(),
            stack_size};
  }
};

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

// The entries of `in` whose next[] has `bit`, in order, into `out`: each thread filters a
// slice, then writes its matches after those of the slices before it.
void filter_queue(const std::vector<uint32_t>& in, const uint8_t* next, uint8_t bit, std::vector<uint32_t>& out,
                  int threads) {
  std::vector<size_t> offsets(static_cast<size_t>(threads) + 1, 0);
  out.resize(in.size());
#pragma omp parallel num_threads(threads)
  {
    const size_t t = static_cast<size_t>(omp_get_thread_num()), n = static_cast<size_t>(omp_get_num_threads());
    const size_t begin = in.size() * t / n, end = in.size() * (t + 1) / n;
    size_t matches = 0;
    for (size_t k = begin; k < end; ++k) matches += (next[in[k]] & bit) ? 1 : 0;
    offsets[t + 1] = matches;
#pragma omp barrier
#pragma omp single
    for (size_t j = 1; j <= n; ++j) offsets[j] += offsets[j - 1];
    size_t at = offsets[t];
    for (size_t k = begin; k < end; ++k)
      if (next[in[k]] & bit) out[at++] = in[k];
#pragma omp barrier
#pragma omp single
    out.resize(offsets[n]);
  }
}

}  // namespace

size_t stream_bytes_per_state(const SceneView& view) {
  const IntegratorKind integrator = view.settings.integrator;
  size_t bytes = 2 * sizeof(uint32_t) + 3 * sizeof(Vec3) + sizeof(Hit) + sizeof(uint8_t);
  // the queues' entries: trace and its compaction partner, shadow, and Whitted's resume
  bytes += (integrator == IntegratorKind::Whitted ? 4 : 3) * sizeof(uint32_t);
  if (integrator == IntegratorKind::Path)
    bytes += 3 * sizeof(Vec3) + sizeof(float) + sizeof(uint32_t) + sizeof(uint8_t);
  if (integrator == IntegratorKind::Path || integrator == IntegratorKind::Whitted)
    bytes += 2 * sizeof(Vec3) + sizeof(float) + sizeof(uint32_t);
  if (integrator == IntegratorKind::Whitted)
    bytes +=
        sizeof(WhittedVertex) + whitted_stack_size(view.settings.max_depth) * sizeof(WhittedTask) + sizeof(uint32_t);
  return bytes;
}

void render_stream(const SceneView& view, const CpuKernelVariant& variant, const StreamTarget& target, int threads,
                   RayCounts& counts, StreamStats& stats,
                   const std::function<void(uint64_t done, uint64_t total)>& progress) {
  const uint32_t samples = target.end - target.begin;
  const uint64_t total = static_cast<uint64_t>(target.count) * samples;
  const size_t width = static_cast<size_t>(std::min<uint64_t>(view.settings.stream_width, total));
  const size_t state_bytes = stream_bytes_per_state(view) * width;
  stats.bytes_per_state = stream_bytes_per_state(view);
  stats.state_bytes = std::max(stats.state_bytes, state_bytes);  // the largest of an adaptive render's passes
  if (width == 0) return;
  const auto refuse = [&](const std::string& why) {
    return InputError("--stream-width " + std::to_string(view.settings.stream_width) + ": " +
                      std::to_string(state_bytes) + " bytes of ray states for " + std::to_string(width) +
                      " samples in flight " + why + "; give a smaller width");
  };
  // Linux lends memory it may not have and kills the process when it is touched: refuse
  // more than half the machine's memory before allocating.
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0 && state_bytes > static_cast<size_t>(pages) * static_cast<size_t>(page_size) / 2)
    throw refuse("exceed half of this machine's memory");
  std::unique_ptr<StreamArrays> arrays;
  std::vector<uint32_t> queue, trace, shadow_queue, resume;
  try {
    arrays = std::make_unique<StreamArrays>(view, width);
    queue.reserve(width);
    trace.reserve(width);
    shadow_queue.reserve(width);
    if (view.settings.integrator == IntegratorKind::Whitted) resume.reserve(width);
  } catch (const std::bad_alloc&) {
    throw refuse("cannot be allocated");
  } catch (const std::length_error&) {
    throw refuse("cannot be allocated");
  }
  const StreamStates states = arrays->states();

  for (uint64_t first = 0; first < total; first += width) {
    const size_t count = static_cast<size_t>(std::min<uint64_t>(width, total - first));
    // Pixel-major: item g is sample begin + g % samples of the (g / samples)-th pixel.
    queue.resize(count);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (size_t i = 0; i < count; ++i) {
      const uint64_t g = first + i;
      const size_t p = static_cast<size_t>(g / samples);
      arrays->pixel[i] = target.pixels ? target.pixels[p] : static_cast<uint32_t>(p);
      arrays->sample[i] = target.begin + static_cast<uint32_t>(g % samples);
      queue[i] = static_cast<uint32_t>(i);
    }
    run_stage(variant, view, StreamStage::Generate, states, queue, count, threads, counts);
    resume.clear();
    while (!queue.empty() || !resume.empty()) {
      ++stats.waves;
      stats.largest_queue = std::max<uint64_t>(stats.largest_queue, queue.size());
      run_stage(variant, view, StreamStage::Closest, states, queue, queue.size(), threads, counts);
      queue.insert(queue.end(), resume.begin(), resume.end());  // shaded without a new hit
      run_stage(variant, view, StreamStage::Shade, states, queue, queue.size(), threads, counts);
      filter_queue(queue, arrays->next.data(), kStreamShadow, shadow_queue, threads);
      stats.shadow_rays += shadow_queue.size();
      run_stage(variant, view, StreamStage::Shadow, states, shadow_queue, shadow_queue.size(), threads, counts);
      // Compaction: the states that trace a ray next, and those shaded again without one.
      if (view.settings.integrator == IntegratorKind::Whitted)
        filter_queue(queue, arrays->next.data(), kStreamResume, resume, threads);
      else
        resume.clear();  // only a Whitted vertex resumes
      filter_queue(queue, arrays->next.data(), kStreamTrace, trace, threads);
      queue.swap(trace);
    }
    // Into the film in pixel-sample order, a pixel per thread.
    const uint64_t first_pixel = first / samples, last_pixel = (first + count - 1) / samples;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t p = static_cast<int64_t>(first_pixel); p <= static_cast<int64_t>(last_pixel); ++p) {
      const uint64_t from = std::max<uint64_t>(first, static_cast<uint64_t>(p) * samples);
      const uint64_t to = std::min<uint64_t>(first + count, static_cast<uint64_t>(p + 1) * samples);
      for (uint64_t g = from; g < to; ++g) {
        const size_t i = static_cast<size_t>(g - first);
        const uint32_t pixel = arrays->pixel[i];
        FilmSum& sum =
            target.film ? target.film[pixel] : (arrays->sample[i] % 2u == 0u ? target.even[pixel] : target.odd[pixel]);
        film_add(sum, arrays->radiance[i]);
      }
    }
    ++stats.batches;
    if (progress) progress(first + count, total);
  }
}

}  // namespace tracer
