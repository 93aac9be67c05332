// Sub-pixel sample positions for the five samplers of docs/scene-format.md, and the
// random pairs every later dimension draws (the lens, then each bounce of the path tracer).
#pragma once
#include "kernel/base/philox.h"
#include "kernel/base/sobol.h"

namespace tracer {

enum class SamplerKind : uint32_t { Center, Grid, Stochastic, Stratified, Sobol };

// Two uniforms for dimension pair `dimension` (the film's, the lens's, each bounce's): the
// Sobol sampler's scrambled Sobol pair, every other sampler's independent Philox pair.
TRACER_HD void draw_uniform2(SamplerKind kind, uint64_t seed, uint32_t pixel, uint32_t sample, uint32_t dimension,
                             float& a, float& b) {
  if (kind == SamplerKind::Sobol)
    sobol_uniform2(seed, pixel, sample, dimension, a, b);
  else
    sample_uniform2(seed, pixel, sample, dimension, a, b);
}

// Offset in [0,1)^2 inside the pixel of sample `s` of `spp`; `grid_n` = sqrt(spp) for the
// grid and stratified samplers (the loader checks that spp is a square).
TRACER_HD void film_offset(SamplerKind kind, uint32_t grid_n, uint64_t seed, uint32_t pixel, uint32_t s, float& ox,
                           float& oy) {
  switch (kind) {
    case SamplerKind::Center: ox = oy = 0.5f; return;
    case SamplerKind::Grid:
      ox = (static_cast<float>(s % grid_n) + 0.5f) / static_cast<float>(grid_n);
      oy = (static_cast<float>(s / grid_n) + 0.5f) / static_cast<float>(grid_n);
      return;
    case SamplerKind::Stochastic:
    case SamplerKind::Sobol: draw_uniform2(kind, seed, pixel, s, kDimFilm, ox, oy); return;
    case SamplerKind::Stratified: {
      float jx, jy;
      sample_uniform2(seed, pixel, s, kDimFilm, jx, jy);
      const float n = static_cast<float>(grid_n);
      // min keeps a jitter that rounds up to the next stratum inside this one
      ox = min_of((static_cast<float>(s % grid_n) + jx) / n, 0x1.fffffep-1f);
      oy = min_of((static_cast<float>(s / grid_n) + jy) / n, 0x1.fffffep-1f);
      return;
    }
  }
}

}  // namespace tracer
