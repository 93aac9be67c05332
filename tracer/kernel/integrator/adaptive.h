// Adaptive sampling's per-pixel decision (docs/path.md, "Adaptive sampling"). A pixel's
// samples are kept in two exact fixed-point sums, of its even and of its odd samples
// (film.h). Their means differ by about twice the standard error of the whole mean (for
// halves of n/2 samples, Var(even - odd) = 4 sigma^2 / n), so half their difference,
// averaged over the channels and divided by the mean's channel average, estimates the
// pixel's relative error. Only integer sums enter it, converted and divided in IEEE double
// (correctly rounded on every CPU and on CUDA), so the estimate, the pixels that stop and
// the image do not depend on threads, tiles, structures, instruction sets or the device.
#pragma once
#include "kernel/base/film.h"

namespace tracer {

// A pixel's error terms from its `samples` samples (at least 2), the even ones in `even`,
// the odd ones in `odd`: the estimated standard error of its mean (half the halves' mean
// difference) and the mean itself, each averaged over the channels.
struct PixelErrorTerms {
  double standard_error, level;
};

TRACER_HD PixelErrorTerms pixel_error_terms(const FilmSum& even, const FilmSum& odd, uint32_t samples) {
  const double n_even = static_cast<double>((samples + 1u) / 2u), n_odd = static_cast<double>(samples / 2u);
  double difference = 0.0, level = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double e = static_cast<double>(even.rgb[c]), o = static_cast<double>(odd.rgb[c]);
    const double d = e / n_even - o / n_odd;
    difference += d < 0.0 ? -d : d;
    level += (e + o) / static_cast<double>(samples);
  }
  return {0.5 * difference / 3.0, level / 3.0};
}

// The pixel's relative error estimate: 0 for a pixel whose halves agree exactly; a pixel
// whose channels average 0 or less but differ between the halves never converges.
TRACER_HD double pixel_relative_error(const FilmSum& even, const FilmSum& odd, uint32_t samples) {
  const PixelErrorTerms t = pixel_error_terms(even, odd, samples);
  if (t.standard_error == 0.0) return 0.0;
  if (!(t.level > 0.0)) return kInfinity;
  return t.standard_error / t.level;
}

// Whether a pixel may stop: its estimate is below the threshold.
TRACER_HD bool pixel_converged(const FilmSum& even, const FilmSum& odd, uint32_t samples, float threshold) {
  return pixel_relative_error(even, odd, samples) < static_cast<double>(threshold);
}

// The decision's first step, for each running pixel: whether it is not yet converged at
// `samples`; with threshold 0 (no per-pixel rule: target_error alone) every pixel runs on.
TRACER_HD uint8_t pixel_unconverged(const FilmSum& even, const FilmSum& odd, uint32_t samples, float threshold) {
  return threshold == 0.0f || !pixel_converged(even, odd, samples, threshold) ? 1u : 0u;
}

// The second step: whether pixel (x, y) keeps sampling: it or one of its eight neighbours is not yet
// converged (`unconverged`: one byte per pixel, row-major, `width` x `height`). Spreading the
// decision to neighbours, as Cycles does, keeps a pixel whose first samples all missed a rare
// contribution (a caustic, a small light) running while the pixels around it find it.
TRACER_HD bool neighbourhood_unconverged(const uint8_t* unconverged, uint32_t width, uint32_t height, uint32_t x,
                                         uint32_t y) {
  const uint32_t x0 = x > 0u ? x - 1u : 0u, x1 = x + 1u < width ? x + 1u : x;
  const uint32_t y0 = y > 0u ? y - 1u : 0u, y1 = y + 1u < height ? y + 1u : y;
  for (uint32_t j = y0; j <= y1; ++j)
    for (uint32_t i = x0; i <= x1; ++i)
      if (unconverged[static_cast<size_t>(j) * width + i]) return true;
  return false;
}

}  // namespace tracer
