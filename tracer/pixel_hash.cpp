#include "pixel_hash.h"

#include <OpenImageIO/imagebufalgo.h>

#include "image_buf.h"

namespace tracer {

std::string pixel_hash(const Image& image) {
  const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height) + " rgb float32";
  return "sha1:" + OIIO::ImageBufAlgo::computePixelHashSHA1(to_image_buf(image), size);
}

}  // namespace tracer
