// A progress bar with ETA on stderr, drawn only when stderr is a terminal. Each update says
// its own total, as the render's progress callbacks do (tiles, pixel-samples or samples,
// whichever the schedule counts), so the bar never measures one unit against another.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace tracer {

// The bar's line: "[####....]  42.0%  1.2s elapsed, ETA 1.7s", the fraction held to [0, 1].
std::string progress_line(uint64_t done, uint64_t total, double elapsed_seconds);

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled);
  void update(uint64_t done, uint64_t total);  // cheap to call often: redraws at most 10 times a second
  void finish();

 private:
  uint64_t total_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace tracer
