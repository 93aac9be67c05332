// A whole image's fixed-point film sums (kernel/base/film.h) for one range of samples: what a
// renderer produces, what a partial file stores, and what `tracer merge` adds up.
#pragma once
#include <vector>

#include "image/image.h"
#include "kernel/base/film.h"
#include "kernel/base/sample_range.h"

namespace tracer {

struct FilmBuffer {
  uint32_t width = 0, height = 0;
  SampleRange range;
  std::vector<FilmSum> pixels;  // row-major from the top-left pixel
};

// The image of a film holding all `spp` samples: each pixel's mean, rounded once.
inline Image resolve_film(const FilmBuffer& film, uint32_t spp) {
  Image image;
  image.width = film.width;
  image.height = film.height;
  image.rgb.resize(film.pixels.size() * 3);
  for (size_t i = 0; i < film.pixels.size(); ++i) {
    const Vec3 v = film_mean(film.pixels[i], spp);
    image.rgb[3 * i] = v.x, image.rgb[3 * i + 1] = v.y, image.rgb[3 * i + 2] = v.z;
  }
  return image;
}

}  // namespace tracer
