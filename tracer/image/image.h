// A linear-RGB float image, row-major from the top-left pixel.
#pragma once
#include <cstdint>
#include <vector>

namespace tracer {

struct Image {
  uint32_t width = 0, height = 0;
  std::vector<float> rgb;  // 3 floats per pixel
};

}  // namespace tracer
