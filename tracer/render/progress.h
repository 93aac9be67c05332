// A progress bar with ETA on stderr, drawn only when stderr is a terminal.
#pragma once
#include <chrono>
#include <cstdint>

namespace tracer {

class ProgressBar {
 public:
  ProgressBar(uint64_t total, bool enabled);
  void update(uint64_t done);  // cheap to call often: redraws at most 10 times a second
  void finish();

 private:
  uint64_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace tracer
