// The CPU scheduler of adaptive sampling (render.noise_threshold; docs/path.md): passes over
// the pixels still running, each ending at a checkpoint (min_spp, then doubling up to spp),
// after which kernel/integrator/adaptive.h decides from each pixel's exact even and odd
// sums whether it stops. A pixel's k-th sample is the uniform render's k-th sample, so a
// pixel that never stops equals the uniform render's pixel bit for bit; the stopped set
// depends on integer sums only, never on threads or the order in which pixels finish.
#pragma once
#include <vector>

#include "image/image.h"
#include "render/render_cpu.h"

namespace tracer {

struct AdaptiveFilm {
  uint32_t width = 0, height = 0;
  std::vector<FilmSum> even, odd;  // per pixel, row-major: the sums of its even and odd samples
  std::vector<uint32_t> samples;   // per pixel: how many it took
  double image_error = 0;          // target_error: the image's estimate at the last checkpoint
};

// Whether the settings ask for adaptive sampling: per pixel (noise_threshold) or for the
// whole image (target_error).
inline bool adaptive_render(const RenderSettings& rs) { return rs.noise_threshold > 0.0f || rs.target_error > 0.0f; }

// The whole image's estimated relative RMS error from its pixels' half sums: the RMS of the
// pixels' standard errors over the RMS of their means (kernel/integrator/adaptive.h).
double image_relative_error(const AdaptiveFilm& film);

// The checkpoints: min(min_spp, spp), then doubling, the last one spp.
std::vector<uint32_t> adaptive_checkpoints(uint32_t min_spp, uint32_t spp);

// Renders every pixel to its first checkpoint, then continues only the pixels whose
// relative error estimate is not yet below settings.noise_threshold (or, with target_error,
// every pixel until the image's estimate is below it), to spp at most.
// `progress` gets (pixel-samples settled, width x height x spp): a stopped pixel's
// remaining samples count as settled. `kernel` (optional) overrides the variant chosen for
// the scene's features.
AdaptiveFilm render_cpu_adaptive(const Scene& scene, int threads, RenderStats& stats,
                                 const ProgressCallback& progress = {}, const CpuKernelVariant* kernel = nullptr);

// Each pixel's mean over its own samples, rounded once.
Image resolve_adaptive(const AdaptiveFilm& film);

// Each pixel's sample count, in all three channels (the sample map users look at).
Image adaptive_sample_map(const AdaptiveFilm& film);

}  // namespace tracer
