// Thin-lens depth of field against geometry: a small square emitter off the focal plane
// blurs, on the focus plane, into the lens disc scaled by |z_o - z_f| / z_o (similar
// triangles through the object point), convolved with the square's image and the pixel.
// Second moments of independent shapes add, so the image's mean squared radius about its
// centre is c^2/2 + 2 s'^2/3 + h^2/6 for a disc of radius c, a square of half-size s' and
// pixels of size h; the test recovers the disc's diameter from it and compares it with the
// prediction within five standard errors over independent renders.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

constexpr double kFocus = 4.0, kObject = 8.0, kAperture = 0.5, kHalfSize = 0.05, kViewHeight = 0.64;
constexpr uint32_t kPixels = 64;

// The disc diameter, in focus-plane units, measured from one render.
double measured_diameter(uint64_t seed) {
  const double vfov = 2 * std::atan(kViewHeight / 2 / kFocus) * 180 / M_PI;
  const std::string s = std::to_string(kHalfSize), z = std::to_string(-kObject);
  const Scene scene =
      test::scene_from(R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 0, 0], "to": [0, 0, -1], "vfov": )" +
                       std::to_string(vfov) + R"(, "aperture": )" + std::to_string(kAperture) +
                       R"(, "focus_distance": )" + std::to_string(kFocus) + R"(},
    "film": {"width": 64, "height": 64},
    "render": {"integrator": "albedo", "spp": 256, "sampler": "stratified", "seed": )" +
                       std::to_string(seed) + R"(},
    "materials": {"lamp": {"type": "emissive", "radiance": [1, 1, 1]}},
    "shapes": [{"type": "quad", "corner": [-)" +
                       s + ", -" + s + ", " + z + R"(], "u": [)" + std::to_string(2 * kHalfSize) +
                       R"(, 0, 0], "v": [0, )" + std::to_string(2 * kHalfSize) + R"(, 0], "material": "lamp"}]})");
  RenderStats stats;
  const Image img = render_cpu(scene, 0, stats);
  const double h = kViewHeight / kPixels;  // pixel size on the focus plane
  double sum = 0, sx = 0, sy = 0, sr2 = 0;
  for (uint32_t y = 0; y < kPixels; ++y)
    for (uint32_t x = 0; x < kPixels; ++x) {
      const double w = img.rgb[3 * (y * kPixels + x)], px = (x + 0.5) * h - kViewHeight / 2,
                   py = (y + 0.5) * h - kViewHeight / 2;
      sum += w, sx += w * px, sy += w * py, sr2 += w * (px * px + py * py);
    }
  const double cx = sx / sum, cy = sy / sum, r2 = sr2 / sum - cx * cx - cy * cy;
  const double square = kHalfSize * kFocus / kObject;
  return 2 * std::sqrt(2 * (r2 - 2 * square * square / 3 - h * h / 6));
}

TEST(ThinLens, OutOfFocusPointBlursIntoThePredictedDisc) {
  const double predicted = kAperture * std::abs(kObject - kFocus) / kObject;  // 2 R |z_o - z_f| / z_o
  std::vector<double> d;
  for (uint64_t seed = 1; seed <= 6; ++seed) d.push_back(measured_diameter(seed));
  double mean = 0, var = 0;
  for (double v : d) mean += v / d.size();
  for (double v : d) var += (v - mean) * (v - mean) / (d.size() - 1);
  const double stderr_ = std::sqrt(var / d.size());
  RecordProperty("measured", std::to_string(mean));
  RecordProperty("predicted", std::to_string(predicted));
  EXPECT_NEAR(mean, predicted, 5 * stderr_)
      << "stderr " << stderr_ << " (" << predicted / (kViewHeight / kPixels) << " pixels)";
  EXPECT_LT(stderr_, 0.02 * predicted) << "enough samples to measure the disc";
}

}  // namespace
}  // namespace tracer
