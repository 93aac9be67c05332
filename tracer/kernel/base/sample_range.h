// A range of sample indices of every pixel: what one render, partial file, bundle or kernel
// launch covers (`--samples A:B`).
#pragma once
#include <cstdint>

namespace tracer {

struct SampleRange {
  uint32_t begin = 0, end = 0;  // samples [begin, end) of every pixel
};

}  // namespace tracer
