#include "render/adaptive_film.h"

#include <algorithm>
#include <cmath>

#include "kernel/integrator/adaptive.h"

namespace tracer {
namespace {

// A pixel's whole sum. Each half stays below 2^62 in magnitude (film.h), so their sum fits
// int64; film_mean divides it in double.
FilmSum whole_sum(const FilmSum& even, const FilmSum& odd) {
  return {{even.rgb[0] + odd.rgb[0], even.rgb[1] + odd.rgb[1], even.rgb[2] + odd.rgb[2]},
          even.nonfinite + odd.nonfinite,
          even.overflow + odd.overflow};
}

// An image of the film's size whose pixel i is value(i).
template <class PixelValue>
Image pixel_image(const AdaptiveFilm& film, const PixelValue& value) {
  Image image;
  image.width = film.width;
  image.height = film.height;
  image.rgb.resize(film.samples.size() * 3);
  for (size_t i = 0; i < film.samples.size(); ++i) {
    const Vec3 v = value(i);
    image.rgb[3 * i] = v.x, image.rgb[3 * i + 1] = v.y, image.rgb[3 * i + 2] = v.z;
  }
  return image;
}

}  // namespace

std::vector<uint32_t> adaptive_checkpoints(uint32_t min_spp, uint32_t spp) {
  std::vector<uint32_t> points = {std::min(min_spp, spp)};
  while (points.back() < spp) points.push_back(static_cast<uint32_t>(std::min<uint64_t>(2ull * points.back(), spp)));
  return points;
}

double image_relative_error(const AdaptiveFilm& film) {
  double errors = 0.0, levels = 0.0;
  for (size_t i = 0; i < film.samples.size(); ++i) {
    const PixelErrorTerms t = pixel_error_terms(film.even[i], film.odd[i], film.samples[i]);
    errors += t.standard_error * t.standard_error;
    levels += t.level * t.level;
  }
  if (errors == 0.0) return 0.0;
  return levels > 0.0 ? std::sqrt(errors / levels) : static_cast<double>(kInfinity);
}

Image resolve_adaptive(const AdaptiveFilm& film) {
  return pixel_image(film, [&](size_t i) { return film_mean(whole_sum(film.even[i], film.odd[i]), film.samples[i]); });
}

Image adaptive_sample_map(const AdaptiveFilm& film) {
  return pixel_image(film, [&](size_t i) {
    const float n = static_cast<float>(film.samples[i]);
    return Vec3{n, n, n};
  });
}

std::vector<uint8_t> keep_running_pixels(const AdaptiveFilm& film, const std::vector<uint32_t>& running,
                                         uint32_t checkpoint, float threshold) {
  std::vector<uint8_t> unconverged(film.samples.size(), 0u), keep(running.size());
  for (const uint32_t p : running) unconverged[p] = pixel_unconverged(film.even[p], film.odd[p], checkpoint, threshold);
  for (size_t i = 0; i < running.size(); ++i)
    keep[i] = neighbourhood_unconverged(unconverged.data(), film.width, film.height, running[i] % film.width,
                                        running[i] / film.width);
  return keep;
}

uint64_t adaptive_nonfinite_samples(const AdaptiveFilm& film) {
  uint64_t n = 0;
  for (size_t i = 0; i < film.even.size(); ++i) n += film.even[i].nonfinite + film.odd[i].nonfinite;
  return n;
}

uint64_t adaptive_overflow_samples(const AdaptiveFilm& film) {
  uint64_t n = 0;
  for (size_t i = 0; i < film.even.size(); ++i) n += film.even[i].overflow + film.odd[i].overflow;
  return n;
}

}  // namespace tracer
