// What the speed/accuracy benchmarks share: a timed render and its error against a
// reference image. RMSE is over all pixels and channels; display RMSE compares values
// clamped to [0, 1], as a display shows them, so the edges of a visible light (whose noise
// comes from the film's antialiasing, the same for every estimator) do not swamp it; relMSE
// is the mean of (x - r)^2 / (r^2 + 0.01) (Rousselle et al. 2011), which weighs dark and
// bright regions alike.
#pragma once
#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace tracer {

struct TimedRender {
  Image image;
  double seconds = 0;  // the render alone, wall clock, all threads; the median of the repeats
  uint64_t rays = 0;
};

struct ImageError {
  double rmse = 0, display_rmse = 0, rel_mse = 0;
};

// The median of `values` (the upper one of an even count); at least one value.
inline double median_value(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The median of `repeats` (at least 1) values of `measure()`.
inline double median_of(uint32_t repeats, const std::function<double()>& measure) {
  std::vector<double> values;
  for (uint32_t r = 0; r < std::max(repeats, 1u); ++r) values.push_back(measure());
  return median_value(std::move(values));
}

// The median of the values `measure()` returns with the seconds it took: over at least
// `repeats` runs and as many more, up to `max_runs`, as fill `fill_seconds`. Five runs of a
// 1 ms build vary by a third from one run of the bench to the next.
struct TimedValue {
  double value, seconds;
};
inline double median_filling(uint32_t repeats, double fill_seconds, size_t max_runs,
                             const std::function<TimedValue()>& measure) {
  std::vector<double> values;
  double total = 0;
  while (values.size() < std::max(repeats, 1u) || (total < fill_seconds && values.size() < max_runs)) {
    const TimedValue run = measure();
    values.push_back(run.value);
    total += run.seconds;
  }
  return median_value(std::move(values));
}

// The median of a build's seconds (`measure()`), repeated to fill 0.25 s (at most 10,000 runs).
inline double median_build_seconds(uint32_t repeats, const std::function<double()>& measure) {
  return median_filling(repeats, 0.25, 10000, [&] {
    const double seconds = measure();
    return TimedValue{seconds, seconds};
  });
}

// Wall seconds of `run()`, the median of `repeats` runs.
inline double median_seconds(uint32_t repeats, const std::function<void()>& run) {
  return median_of(repeats, [&] {
    const auto start = std::chrono::steady_clock::now();
    run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
}

// Renders `repeats` times (the image is the same each time) and keeps the median time.
TimedRender timed_render(const Scene& scene, int threads, int repeats = 1);
ImageError image_error(const Image& image, const Image& reference);

// The reference: `ref_file` when given (it must match the size), else the scene rendered
// at ref_spp samples with a seed no measured render uses, saved as `save_as` in
// bench_reference_dir() for --ref next time. Prints what it used.
Image reference_image(const std::string& scene_path, RenderOverrides overrides, const std::string& ref_file,
                      uint64_t ref_spp, int threads, const std::string& save_as);

// Where benchmarks save the references they render: bench-refs/ beside the tracer binary
// (build/bench-refs/), never the source tree or the working directory.
std::string bench_reference_dir();

// "1,4,16" to numbers; InputError naming the option.
std::vector<uint32_t> parse_spp_list(const std::string& option, const std::string& text);

}  // namespace tracer
