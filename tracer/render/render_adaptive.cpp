#include "render/render_adaptive.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "kernel/integrator/adaptive.h"
#include "render/cpu_kernel.h"

namespace tracer {
namespace {

constexpr size_t kChunk = 64;  // pixels per work item: small enough to balance 2 to 64 threads

FilmSum combined(const FilmSum& a, const FilmSum& b) {
  return {{a.rgb[0] + b.rgb[0], a.rgb[1] + b.rgb[1], a.rgb[2] + b.rgb[2]},
          a.nonfinite + b.nonfinite,
          a.overflow + b.overflow};
}

// An image of the film's size whose pixel i is value(i).
template <class PixelValue>
Image pixel_image(const AdaptiveFilm& film, const PixelValue& value) {
  Image image;
  image.width = film.width;
  image.height = film.height;
  image.rgb.resize(film.samples.size() * 3);
  for (size_t i = 0; i < film.samples.size(); ++i) {
    const Vec3 v = value(i);
    image.rgb[3 * i] = v.x, image.rgb[3 * i + 1] = v.y, image.rgb[3 * i + 2] = v.z;
  }
  return image;
}

}  // namespace

std::vector<uint32_t> adaptive_checkpoints(uint32_t min_spp, uint32_t spp) {
  std::vector<uint32_t> points = {std::min(min_spp, spp)};
  while (points.back() < spp) points.push_back(static_cast<uint32_t>(std::min<uint64_t>(2ull * points.back(), spp)));
  return points;
}

AdaptiveFilm render_cpu_adaptive(const Scene& scene, int threads, RenderStats& stats, const ProgressCallback& progress,
                                 const CpuKernelVariant* kernel) {
  const SceneView view = scene.view();
  const CpuKernelVariant& variant = kernel ? *kernel : cpu_kernel_for(view.features);
  const RenderSettings& rs = view.settings;
  const size_t n = static_cast<size_t>(rs.width) * rs.height;
  AdaptiveFilm film;
  film.width = rs.width;
  film.height = rs.height;
  film.even.assign(n, FilmSum{{0, 0, 0}, 0u, 0u});
  film.odd.assign(n, FilmSum{{0, 0, 0}, 0u, 0u});
  film.samples.assign(n, 0u);
  std::vector<uint8_t> unconverged(n);  // at the last checkpoint, per pixel
  std::vector<uint32_t> running(n);
  for (size_t i = 0; i < n; ++i) running[i] = static_cast<uint32_t>(i);

  const uint64_t total = static_cast<uint64_t>(n) * rs.spp;
  std::atomic<uint64_t> settled{0};
  uint64_t camera = 0, secondary = 0, shadow = 0;
  const int nthreads = threads > 0 ? threads : omp_get_max_threads();
  uint32_t begin = 0;
  for (const uint32_t checkpoint : adaptive_checkpoints(rs.min_spp, rs.spp)) {
    const int64_t chunks = static_cast<int64_t>((running.size() + kChunk - 1) / kChunk);
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads) reduction(+ : camera, secondary, shadow)
    for (int64_t c = 0; c < chunks; ++c) {
      const size_t first = static_cast<size_t>(c) * kChunk, count = std::min(kChunk, running.size() - first);
      RayCounts counts{};
      variant.render_pixels_halves(view, running.data() + first, count, begin, checkpoint, film.even.data(),
                                   film.odd.data(), counts);
      camera += counts.camera;
      secondary += counts.secondary;
      shadow += counts.shadow;
      const uint64_t done = settled.fetch_add(count * (checkpoint - begin)) + count * (checkpoint - begin);
      if (progress && omp_get_thread_num() == 0) progress(done, total);
    }
    // The decision, in pixel order on one thread: the kept list is the same for any thread count.
    std::fill(unconverged.begin(), unconverged.end(), 0);
    for (const uint32_t p : running) film.samples[p] = checkpoint;
    if (rs.target_error > 0.0f) film.image_error = image_relative_error(film);
    const bool image_done = rs.target_error > 0.0f && film.image_error < static_cast<double>(rs.target_error);
    for (const uint32_t p : running)
      unconverged[p] =
          checkpoint < rs.spp && !image_done &&
          (rs.noise_threshold == 0.0f || !pixel_converged(film.even[p], film.odd[p], checkpoint, rs.noise_threshold));
    std::vector<uint32_t> kept;
    for (const uint32_t p : running) {
      if (checkpoint < rs.spp &&
          neighbourhood_unconverged(unconverged.data(), rs.width, rs.height, p % rs.width, p / rs.width))
        kept.push_back(p);
      else
        settled.fetch_add(rs.spp - checkpoint);
    }
    running.swap(kept);
    begin = checkpoint;
    if (running.empty()) break;
  }
  if (progress) progress(total, total);
  stats.rays = {camera, secondary, shadow};
  stats.nonfinite_samples = stats.overflow_samples = 0;
  for (size_t i = 0; i < n; ++i) {
    stats.nonfinite_samples += film.even[i].nonfinite + film.odd[i].nonfinite;
    stats.overflow_samples += film.even[i].overflow + film.odd[i].overflow;
  }
  stats.cpu_kernel = cpu_kernel_name(variant);
  return film;
}

double image_relative_error(const AdaptiveFilm& film) {
  double errors = 0.0, levels = 0.0;
  for (size_t i = 0; i < film.samples.size(); ++i) {
    const PixelErrorTerms t = pixel_error_terms(film.even[i], film.odd[i], film.samples[i]);
    errors += t.standard_error * t.standard_error;
    levels += t.level * t.level;
  }
  if (errors == 0.0) return 0.0;
  return levels > 0.0 ? std::sqrt(errors / levels) : static_cast<double>(kInfinity);
}

Image resolve_adaptive(const AdaptiveFilm& film) {
  return pixel_image(film, [&](size_t i) { return film_mean(combined(film.even[i], film.odd[i]), film.samples[i]); });
}

Image adaptive_sample_map(const AdaptiveFilm& film) {
  return pixel_image(film, [&](size_t i) {
    const float n = static_cast<float>(film.samples[i]);
    return Vec3{n, n, n};
  });
}

}  // namespace tracer
