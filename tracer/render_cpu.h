// The CPU scheduler: OpenMP over 16x16 tiles around kernel/render_pixel.h. Each pixel is
// computed by one thread from plain arrays, so the image does not depend on the thread
// count or on the order in which tiles finish.
#pragma once
#include <functional>

#include "image.h"
#include "kernel/whitted.h"
#include "scene.h"

namespace tracer {

struct RenderStats {
  RayCounts rays{};
  uint64_t nonfinite_samples = 0;
};

// `threads` 0 uses OpenMP's default; `progress` (optional) is called from one thread with
// the number of finished tiles and the total.
Image render_cpu(const Scene& scene, int threads, RenderStats& stats,
                 const std::function<void(uint64_t, uint64_t)>& progress = {});

}  // namespace tracer
