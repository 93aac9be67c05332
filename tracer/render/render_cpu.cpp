#include "render/render_cpu.h"

#include <omp.h>

#include <atomic>

#include "render/cpu_kernel.h"
#include "render/render_adaptive.h"
#include "render/render_stream.h"

namespace tracer {

FilmBuffer render_cpu_film(const Scene& scene, SampleRange range, int threads, RenderStats& stats,
                           const ProgressCallback& progress, const CpuKernelVariant* kernel) {
  constexpr uint32_t kTile = 16;
  const SceneView view = scene.view();
  const CpuKernelVariant& variant = kernel ? *kernel : cpu_kernel_for(view.features);
  const uint32_t w = view.settings.width, h = view.settings.height;
  FilmBuffer film;
  film.width = w;
  film.height = h;
  film.range = range;
  film.pixels.resize(static_cast<size_t>(w) * h);
  const uint32_t tiles_x = (w + kTile - 1) / kTile, tiles_y = (h + kTile - 1) / kTile;
  const int64_t tile_count = static_cast<int64_t>(tiles_x) * tiles_y;
  std::atomic<uint64_t> tiles_done{0};
  uint64_t camera = 0, secondary = 0, shadow = 0, nonfinite = 0, overflow = 0;
  const int nthreads = threads > 0 ? threads : omp_get_max_threads();
  stats.cpu_kernel = cpu_kernel_name(variant);
  if (view.settings.schedule == Schedule::Stream) {
    RayCounts counts{};
    const StreamTarget target = {nullptr, film.pixels.size(), range.begin, range.end, film.pixels.data(), nullptr,
                                 nullptr};
    render_stream(view, variant, target, nthreads, counts, stats.stream, progress);
    stats.rays = counts;
    for (const FilmSum& sum : film.pixels) {
      stats.nonfinite_samples += sum.nonfinite;
      stats.overflow_samples += sum.overflow;
    }
    return film;
  }

#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads) reduction(+ : camera, secondary, shadow, nonfinite, overflow)
  for (int64_t tile = 0; tile < tile_count; ++tile) {
    const uint32_t x0 = static_cast<uint32_t>(tile % tiles_x) * kTile,
                   y0 = static_cast<uint32_t>(tile / tiles_x) * kTile;
    RayCounts counts{};
    const uint32_t x1 = std::min(x0 + kTile, w), y1 = std::min(y0 + kTile, h);
    variant.render_tile(view, x0, y0, x1, y1, range.begin, range.end, film.pixels.data(), counts);
    for (uint32_t y = y0; y < y1; ++y) {
      for (uint32_t x = x0; x < x1; ++x) {
        const FilmSum& sum = film.pixels[static_cast<size_t>(y) * w + x];
        nonfinite += sum.nonfinite;
        overflow += sum.overflow;
      }
    }
    camera += counts.camera;
    secondary += counts.secondary;
    shadow += counts.shadow;
    const uint64_t done = tiles_done.fetch_add(1) + 1;
    if (progress && omp_get_thread_num() == 0) progress(done, static_cast<uint64_t>(tile_count));
  }
  stats.rays = {camera, secondary, shadow};
  stats.nonfinite_samples = nonfinite;
  stats.overflow_samples = overflow;
  return film;
}

Image render_cpu(const Scene& scene, int threads, RenderStats& stats, const ProgressCallback& progress) {
  if (adaptive_render(scene.settings)) return resolve_adaptive(render_cpu_adaptive(scene, threads, stats, progress));
  const uint32_t spp = scene.settings.spp;
  return resolve_film(render_cpu_film(scene, {0, spp}, threads, stats, progress), spp);
}

}  // namespace tracer
