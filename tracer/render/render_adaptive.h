// The tracer's CPU scheduler of adaptive sampling (render.noise_threshold, render.target_error;
// docs/path.md): render/adaptive_schedule.h's loop with OpenMP passes over the running
// pixels, 64 per work item, through the CPU kernel variant chosen for the scene. A pixel's
// k-th sample is the uniform render's k-th sample, so a pixel that never stops equals the
// uniform render's pixel bit for bit.
#pragma once
#include "render/adaptive_film.h"
#include "render/render_cpu.h"

namespace tracer {

// Renders every pixel to its first checkpoint, then continues only the pixels whose
// relative error estimate is not yet below settings.noise_threshold (or, with target_error,
// every pixel until the image's estimate is below it), to spp at most.
// `progress` gets (pixel-samples settled, width x height x spp): a stopped pixel's
// remaining samples count as settled. `kernel` (optional) overrides the variant chosen for
// the scene's features.
AdaptiveFilm render_cpu_adaptive(const Scene& scene, int threads, RenderStats& stats,
                                 const ProgressCallback& progress = {}, const CpuKernelVariant* kernel = nullptr);

}  // namespace tracer
