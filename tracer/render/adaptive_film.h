// What an adaptive render (render.noise_threshold, render.target_error; docs/path.md) leaves:
// each pixel's exact sums of its even and of its odd samples and its own sample count, and
// the functions every scheduler shares to read them (the tracer's OpenMP one, the runner's
// CPU one and the GPU's): the checkpoints, the image's error estimate, the image and the
// sample map. Plain C++: the self-contained runner links it.
#pragma once
#include <vector>

#include "image/image.h"
#include "kernel/base/film.h"
#include "kernel/scene/render_settings.h"

namespace tracer {

struct AdaptiveFilm {
  uint32_t width = 0, height = 0;
  std::vector<FilmSum> even, odd;  // per pixel, row-major: the sums of its even and odd samples
  std::vector<uint32_t> samples;   // per pixel: how many it took
  double image_error = 0;          // target_error: the image's estimate at the last checkpoint
};

// The checkpoints: min(min_spp, spp), then doubling, the last one spp.
std::vector<uint32_t> adaptive_checkpoints(uint32_t min_spp, uint32_t spp);

// The whole image's estimated relative RMS error from its pixels' half sums: the RMS of the
// pixels' standard errors over the RMS of their means (kernel/integrator/adaptive.h), summed
// in pixel order.
double image_relative_error(const AdaptiveFilm& film);

// Each pixel's mean over its own samples, rounded once.
Image resolve_adaptive(const AdaptiveFilm& film);

// Each pixel's sample count, in all three channels (the sample map users look at).
Image adaptive_sample_map(const AdaptiveFilm& film);

// The decision after `checkpoint` on the host, for each running pixel in order: whether it
// keeps sampling (kernel/integrator/adaptive.h's two steps; the CPU backends' keep()).
std::vector<uint8_t> keep_running_pixels(const AdaptiveFilm& film, const std::vector<uint32_t>& running,
                                         uint32_t checkpoint, float threshold);

// The ray and sample counters of a film: NaN/inf and out-of-range samples over every pixel.
uint64_t adaptive_nonfinite_samples(const AdaptiveFilm& film);
uint64_t adaptive_overflow_samples(const AdaptiveFilm& film);

}  // namespace tracer
