// Where a stream render's samples go (kernel/integrator/stream.h adds them there): plain data
// that the host loop (render/stream_schedule.h) and every backend share.
#pragma once
#include <cstddef>
#include <cstdint>

#include "kernel/base/film.h"
#include "kernel/base/vec3.h"

namespace tracer {

// Where a stream render's samples go: samples [begin, end) of pixels[0..count) (indices
// y * width + x; every pixel in order when `pixels` is null, count = width * height), added
// to film[pixel], or by sample parity to even[pixel] and odd[pixel] (adaptive sampling), or
// each item's radiance stored at samples[item] (the parity case of the stages).
struct StreamTarget {
  const uint32_t* pixels;
  size_t count;
  uint32_t begin, end;
  FilmSum* film;
  FilmSum* even;
  FilmSum* odd;
  Vec3* samples = nullptr;
};

}  // namespace tracer
