// A hash of an image's pixel data (not of its file): "sha1:" and 40 hex digits, the value
// OpenImageIO's computePixelHashSHA1 gives: SHA-1 of the float32 RGB values, then the size.
// Two images have the same hash exactly when their floats are identical bit for bit
// (barring a SHA-1 collision), whatever file format or compression carried them.
#pragma once
#include <string>

#include "image/image.h"

namespace tracer {

std::string pixel_hash(const Image& image);

}  // namespace tracer
