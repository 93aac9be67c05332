// Sub-pixel sample positions for the four samplers of docs/scene-format.md.
#pragma once
#include "kernel/base/philox.h"

namespace tracer {

enum class SamplerKind : uint32_t { Center, Grid, Stochastic, Stratified };

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
    case SamplerKind::Stochastic: sample_uniform2(seed, pixel, s, kDimFilm, ox, oy); return;
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
