// The runner's CPU scheduler of adaptive sampling: render/adaptive_schedule.h's loop with
// passes on std::threads (parallel_for) and the decision on the host, the film the tracer's
// OpenMP scheduler and the GPU's produce, bit for bit.
#pragma once
#include "kernel/integrator/render_pixel.h"
#include "parity/cpu_stream.h"
#include "parity/parallel_for.h"
#include "render/adaptive_schedule.h"

namespace tracer {

struct CpuAdaptiveFilm {
  AdaptiveFilm film;
  RayCounts rays{};
};

inline CpuAdaptiveFilm render_adaptive_on_cpu(const SceneView& view, unsigned threads) {
  struct Backend {
    const SceneView& view;
    unsigned threads;
    RayCounts rays{};

    void render(AdaptiveFilm& film, const std::vector<uint32_t>& running, uint32_t begin, uint32_t end, uint64_t) {
      if (view.settings.schedule == Schedule::Stream) {
        StreamStats stats;
        const StreamTarget target = {running.data(), running.size(),   begin,          end,
                                     nullptr,        film.even.data(), film.odd.data()};
        render_stream_on_cpu(view, target, threads, rays, stats);
        return;
      }
      std::vector<RayCounts> counts(running.size(), RayCounts{0, 0, 0});
      parallel_for(running.size(), threads, [&](size_t i) {
        const uint32_t p = running[i];
        render_pixel_halves(view, p % film.width, p / film.width, begin, end, film.even[p], film.odd[p], counts[i]);
      });
      for (const RayCounts& c : counts) rays.camera += c.camera, rays.secondary += c.secondary, rays.shadow += c.shadow;
    }
    void read_sums(AdaptiveFilm&) {}  // the passes add into the film itself
    std::vector<uint8_t> keep(AdaptiveFilm& film, const std::vector<uint32_t>& running, uint32_t checkpoint,
                              float threshold) {
      return keep_running_pixels(film, running, checkpoint, threshold);
    }
  };
  Backend backend{view, threads};
  CpuAdaptiveFilm r;
  r.film = schedule_adaptive(view.settings, backend);
  r.rays = backend.rays;
  return r;
}

}  // namespace tracer
