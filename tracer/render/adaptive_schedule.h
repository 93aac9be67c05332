// The host loop of adaptive sampling (docs/path.md, "Adaptive sampling"), shared by every
// scheduler: the tracer's OpenMP one (render_adaptive.cpp), the runner's CPU one and the GPU's
// (cuda/gpu_adaptive.cu). Passes over the pixels still running end at the checkpoints; after
// each, the backend applies the per-pixel decision of kernel/integrator/adaptive.h and the
// loop keeps the running pixels it flags, in pixel order. Every decision reads integer sums
// only, so the film is the same whichever backend, thread count or device ran the passes.
//
// A backend has
//   void render(AdaptiveFilm&, const std::vector<uint32_t>& running, uint32_t begin, uint32_t end,
//               uint64_t settled)  samples [begin, end) of the running pixels; `settled`:
//                                  pixel-samples already settled, for progress
//   void read_sums(AdaptiveFilm&)  brings every pixel's even and odd sums into the film
//   std::vector<uint8_t> keep(AdaptiveFilm&, const std::vector<uint32_t>& running, uint32_t checkpoint,
//                             float threshold)  per running pixel, in order: neighbourhood_unconverged
//                                               over a map where pixel_unconverged marked the running
//                                               pixels and every stopped pixel is 0
#pragma once
#include <functional>

#include "render/adaptive_film.h"

namespace tracer {

template <class Backend>
AdaptiveFilm schedule_adaptive(const RenderSettings& rs, Backend& backend,
                               const std::function<void(uint64_t, uint64_t)>& progress = {}) {
  const size_t n = static_cast<size_t>(rs.width) * rs.height;
  AdaptiveFilm film;
  film.width = rs.width;
  film.height = rs.height;
  film.even.assign(n, FilmSum{{0, 0, 0}, 0u, 0u});
  film.odd.assign(n, FilmSum{{0, 0, 0}, 0u, 0u});
  film.samples.assign(n, 0u);
  std::vector<uint32_t> running(n);
  for (size_t i = 0; i < n; ++i) running[i] = static_cast<uint32_t>(i);

  const uint64_t total = static_cast<uint64_t>(n) * rs.spp;
  uint64_t settled = 0;
  uint32_t begin = 0;
  bool sums_read = false;  // the film's sums are the backend's (a GPU backend downloads them)
  for (const uint32_t checkpoint : adaptive_checkpoints(rs.min_spp, rs.spp)) {
    backend.render(film, running, begin, checkpoint, settled);
    sums_read = false;
    settled += static_cast<uint64_t>(running.size()) * (checkpoint - begin);
    for (const uint32_t p : running) film.samples[p] = checkpoint;
    bool image_done = false;
    if (rs.target_error > 0.0f) {
      backend.read_sums(film);
      sums_read = true;
      film.image_error = image_relative_error(film);
      image_done = film.image_error < static_cast<double>(rs.target_error);
    }
    begin = checkpoint;
    if (checkpoint == rs.spp || image_done) break;
    // Without a per-pixel threshold (target_error alone) every pixel keeps running.
    const std::vector<uint8_t> keep = backend.keep(film, running, checkpoint, rs.noise_threshold);
    std::vector<uint32_t> kept;
    for (size_t i = 0; i < running.size(); ++i) {
      if (keep[i])
        kept.push_back(running[i]);
      else
        settled += rs.spp - checkpoint;
    }
    running.swap(kept);
    if (progress) progress(settled, total);
    if (running.empty()) break;
  }
  if (!sums_read) backend.read_sums(film);
  if (progress) progress(total, total);
  return film;
}

}  // namespace tracer
