#include "render/render_adaptive.h"

#include <omp.h>

#include <algorithm>
#include <atomic>

#include "render/adaptive_schedule.h"
#include "render/cpu_kernel.h"
#include "render/render_stream.h"

namespace tracer {
namespace {

constexpr size_t kChunk = 64;  // pixels per work item: small enough to balance 2 to 64 threads

struct OpenMpBackend {
  const SceneView& view;
  const CpuKernelVariant& variant;
  int threads;
  const ProgressCallback& progress;
  uint64_t total;
  uint64_t camera = 0, secondary = 0, shadow = 0;
  StreamStats stream;

  void render(AdaptiveFilm& film, const std::vector<uint32_t>& running, uint32_t begin, uint32_t end,
              uint64_t settled_before) {
    if (view.settings.schedule == Schedule::Stream) {
      RayCounts counts{};
      const StreamTarget target = {running.data(), running.size(),   begin,          end,
                                   nullptr,        film.even.data(), film.odd.data()};
      const auto batch_done = [&](uint64_t done, uint64_t) {
        if (progress) progress(settled_before + done, total);
      };
      render_stream(view, variant, target, threads, counts, stream, batch_done);
      camera += counts.camera, secondary += counts.secondary, shadow += counts.shadow;
      return;
    }
    const int64_t chunks = static_cast<int64_t>((running.size() + kChunk - 1) / kChunk);
    std::atomic<uint64_t> settled{settled_before};
    uint64_t c_camera = 0, c_secondary = 0, c_shadow = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(+ : c_camera, c_secondary, c_shadow)
    for (int64_t c = 0; c < chunks; ++c) {
      const size_t first = static_cast<size_t>(c) * kChunk, count = std::min(kChunk, running.size() - first);
      RayCounts counts{};
      variant.render_pixels_halves(view, running.data() + first, count, begin, end, film.even.data(), film.odd.data(),
                                   counts);
      c_camera += counts.camera;
      c_secondary += counts.secondary;
      c_shadow += counts.shadow;
      const uint64_t done = settled.fetch_add(count * (end - begin)) + count * (end - begin);
      if (progress && omp_get_thread_num() == 0) progress(done, total);
    }
    camera += c_camera, secondary += c_secondary, shadow += c_shadow;
  }

  void read_sums(AdaptiveFilm&) {}  // the passes add into the film itself

  std::vector<uint8_t> keep(AdaptiveFilm& film, const std::vector<uint32_t>& running, uint32_t checkpoint,
                            float threshold) {
    return keep_running_pixels(film, running, checkpoint, threshold);
  }
};

}  // namespace

AdaptiveFilm render_cpu_adaptive(const Scene& scene, int threads, RenderStats& stats, const ProgressCallback& progress,
                                 const CpuKernelVariant* kernel) {
  const SceneView view = scene.view();
  const RenderSettings& rs = view.settings;
  OpenMpBackend backend{view, kernel ? *kernel : cpu_kernel_for(view.features),
                        threads > 0 ? threads : omp_get_max_threads(), progress,
                        static_cast<uint64_t>(rs.width) * rs.height * rs.spp, 0, 0, 0, {}};
  AdaptiveFilm film = schedule_adaptive(rs, backend, progress);
  stats.rays = {backend.camera, backend.secondary, backend.shadow};
  stats.nonfinite_samples = adaptive_nonfinite_samples(film);
  stats.overflow_samples = adaptive_overflow_samples(film);
  stats.cpu_kernel = cpu_kernel_name(backend.variant);
  stats.stream = backend.stream;
  return film;
}

}  // namespace tracer
