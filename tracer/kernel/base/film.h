// Film accumulation in 64-bit fixed point (docs/determinism.md rule 5). Each sample's radiance is
// rounded to a multiple of 2^-32 and the integers are added; integer addition is
// associative, so sums of sample ranges rendered apart (by threads, devices or machines)
// add up to exactly the sum of all samples, and the merged image equals the whole render
// bit for bit. A sample that is NaN or infinite, or one of 2^30 or more (or that would
// overflow the sum), is rejected and counted as non-finite or as overflow, never added.
#pragma once
#include "kernel/base/float_to_int.h"
#include "kernel/base/vec3.h"

namespace tracer {

constexpr double kFilmUnits = 4294967296.0;              // 2^32 film units per unit of radiance
constexpr double kFilmSampleLimit = 1073741824.0;        // 2^30: larger samples are rejected
constexpr int64_t kFilmSumLimit = 0x3fffffffffffffffll;  // |sum| stays below 2^62

struct FilmSum {
  int64_t rgb[3];
  uint32_t nonfinite;  // samples left out for a NaN or inf component
  uint32_t overflow;   // samples left out for a finite component beyond the film's range
};

// Rounds to the nearest film unit, halves away from zero (only + - * and conversions).
TRACER_HD int64_t to_film_units(float v) {
  const double x = static_cast<double>(v) * kFilmUnits;
  return trunc_to_int64(x >= 0.0 ? x + 0.5 : x - 0.5);
}

// Adds one sample; false (and counted) when it is rejected.
TRACER_HD bool film_add(FilmSum& sum, Vec3 v) {
  const float c[3] = {v.x, v.y, v.z};
  int64_t units[3];
  for (int i = 0; i < 3; ++i) {
    if (!(c[i] - c[i] == 0.0f)) {  // NaN or inf
      ++sum.nonfinite;
      return false;
    }
    if (!(abs_of(c[i]) < static_cast<float>(kFilmSampleLimit))) {
      ++sum.overflow;
      return false;
    }
    units[i] = to_film_units(c[i]);
    const int64_t next = sum.rgb[i] + units[i];  // |sum| < 2^62 and |units| < 2^62: no overflow
    if (next > kFilmSumLimit || next < -kFilmSumLimit) {
      ++sum.overflow;
      return false;
    }
  }
  for (int i = 0; i < 3; ++i) sum.rgb[i] += units[i];
  return true;
}

// The mean over `samples` samples, rounded once to float.
TRACER_HD Vec3 film_mean(const FilmSum& sum, uint32_t samples) {
  const double scale = kFilmUnits * static_cast<double>(samples);
  return {static_cast<float>(static_cast<double>(sum.rgb[0]) / scale),
          static_cast<float>(static_cast<double>(sum.rgb[1]) / scale),
          static_cast<float>(static_cast<double>(sum.rgb[2]) / scale)};
}

}  // namespace tracer
