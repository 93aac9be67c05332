#include "render/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace tracer {

std::string progress_line(uint64_t done, uint64_t total, double elapsed) {
  const double fraction = total == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  constexpr int kWidth = 40;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(kWidth, '.');
  std::fill(bar.begin(), bar.begin() + filled, '#');
  char text[128];
  std::snprintf(text, sizeof text, "[%s] %5.1f%%  %.1fs elapsed, ETA %.1fs ", bar.c_str(), 100.0 * fraction, elapsed,
                eta);
  return text;
}

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled && isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressBar::update(uint64_t done, uint64_t total) {
  if (!enabled_) return;
  total_ = total;
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  std::fprintf(stderr, "\r%s", progress_line(done, total, std::chrono::duration<double>(now - start_).count()).c_str());
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!enabled_) return;
  update(total_, total_);
  std::fprintf(stderr, "\n");
}

}  // namespace tracer
