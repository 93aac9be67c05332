// The CPU scheduler: OpenMP over 16x16 tiles around kernel/integrator/render_pixel.h. Each pixel is
// computed by one thread from plain arrays into its fixed-point film sum, so the image does
// not depend on the thread count, the order in which tiles finish, or how the samples are
// split into ranges.
#pragma once
#include <functional>

#include "image/image.h"
#include "kernel/integrator/ray_counts.h"
#include "render/cpu_kernel.h"
#include "render/film_buffer.h"
#include "render/render_stream.h"
#include "scene/scene.h"

namespace tracer {

struct RenderStats {
  RayCounts rays{};
  uint64_t nonfinite_samples = 0;  // rejected by the film: a NaN or inf component
  uint64_t overflow_samples = 0;   // rejected by the film: a component, or the pixel's sum, of 2^30 or more
  std::string cpu_kernel;          // the CPU kernel variant that rendered (render/cpu_kernel.h)
  StreamStats stream;              // the stream schedule's queues and memory (zero for the megakernel)
};

using ProgressCallback = std::function<void(uint64_t done, uint64_t total)>;

// Samples `range` of every pixel. `threads` 0 uses OpenMP's default; `progress` (optional)
// is called from one thread with the number of finished tiles (stream: samples) and the total. `kernel`
// (optional) overrides the variant chosen for the scene's features.
FilmBuffer render_cpu_film(const Scene& scene, SampleRange range, int threads, RenderStats& stats,
                           const ProgressCallback& progress = {}, const CpuKernelVariant* kernel = nullptr);

// All samples, resolved to an image; adaptively (render_adaptive.h) when the scene sets
// noise_threshold or target_error.
Image render_cpu(const Scene& scene, int threads, RenderStats& stats, const ProgressCallback& progress = {});

}  // namespace tracer
