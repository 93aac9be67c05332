// The runner's CPU scheduler: kernel/integrator/render_pixel.h for every pixel on std::threads (the
// OpenMP runtime is a shared library the bare GPU machine lacks), or the stream schedule
// (cpu_stream.h). Pixels do not depend on
// the thread that computes them, so this film equals the tracer's OpenMP film bit for bit.
#pragma once
#include "kernel/integrator/render_pixel.h"
#include "parity/cpu_stream.h"
#include "parity/parallel_for.h"
#include "render/film_buffer.h"

namespace tracer {

struct CpuFilm {
  FilmBuffer film;
  RayCounts rays{};
  uint64_t nonfinite = 0, overflow = 0;
};

inline CpuFilm render_film_on_cpu(const SceneView& view, SampleRange range, unsigned threads) {
  const uint32_t w = view.settings.width, h = view.settings.height;
  CpuFilm r;
  r.film = {w, h, range, std::vector<FilmSum>(static_cast<size_t>(w) * h)};
  if (view.settings.schedule == Schedule::Stream) {
    StreamStats stats;
    const StreamTarget target = {nullptr, r.film.pixels.size(), range.begin, range.end, r.film.pixels.data(), nullptr,
                                 nullptr};
    render_stream_on_cpu(view, target, threads, r.rays, stats);
    for (const FilmSum& sum : r.film.pixels) r.nonfinite += sum.nonfinite, r.overflow += sum.overflow;
    return r;
  }
  std::vector<RayCounts> counts(r.film.pixels.size(), RayCounts{0, 0, 0});
  parallel_for(r.film.pixels.size(), threads, [&](size_t i) {
    r.film.pixels[i] = render_pixel(view, static_cast<uint32_t>(i % w), static_cast<uint32_t>(i / w), range.begin,
                                    range.end, counts[i]);
  });
  for (size_t i = 0; i < counts.size(); ++i) {
    r.rays.camera += counts[i].camera, r.rays.secondary += counts[i].secondary, r.rays.shadow += counts[i].shadow;
    r.nonfinite += r.film.pixels[i].nonfinite, r.overflow += r.film.pixels[i].overflow;
  }
  return r;
}

}  // namespace tracer
