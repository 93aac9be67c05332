// Image comparison with idiff's semantics, through OIIO's ImageBufAlgo::compare: a pixel
// fails when any channel differs by more than `fail`, and the comparison fails when more
// than `failpercent` % of pixels fail. fail == 0 means bit-exact: the float data must be
// identical bit for bit (so -0 vs +0 and differing NaN payloads fail too).
#pragma once
#include <cstdint>
#include <string>

#include "image/image.h"

namespace tracer {

struct CompareOptions {
  float fail = 1e-6f;  // idiff's default thresholds
  float failpercent = 0.0f;
  float warn = 1e-6f;
  float warnpercent = 0.0f;
};

enum class Verdict { Pass, Warn, Fail };

struct CompareResult {
  double mean_error = 0, rms_error = 0, psnr = 0, max_error = 0;
  int max_x = 0, max_y = 0;
  uint64_t pixels = 0, pixels_over_warn = 0, pixels_over_fail = 0;
  uint64_t pixels_not_identical = 0;  // pixels whose floats differ in any bit
  bool same_size = true;
  bool bit_identical = false;
  Verdict verdict = Verdict::Fail;
};

CompareResult compare_images(const Image& a, const Image& b, const CompareOptions& options);
Image difference_image(const Image& a, const Image& b);  // |a - b| per channel
std::string describe(const CompareResult& r);            // one line of metrics

}  // namespace tracer
