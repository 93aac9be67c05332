#include "image/pixel_hash.h"

#include "io/sha1.h"

namespace tracer {

// OpenImageIO's computePixelHashSHA1 over a whole float RGB image: the SHA-1 of the pixels'
// bytes followed by the extra text naming the size, here computed without OpenImageIO so
// that the GPU runner (cuda/runner/) gives the same hash.
std::string pixel_hash(const Image& image) {
  const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height) + " rgb float32";
  Sha1 sha;
  sha.append(image.rgb.data(), image.rgb.size() * sizeof(float));
  sha.append(size.data(), size.size());
  return "sha1:" + sha.hex_digest();
}

}  // namespace tracer
