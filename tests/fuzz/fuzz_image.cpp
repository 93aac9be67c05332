// Fuzz target: an image file through read_image_pixels (image/image_io.h), the one reader of
// compare, golden references and textures: OpenImageIO's readers behind our header checks.
// The first byte picks the file's extension (and so the reader OpenImageIO tries first); the
// side limit is lowered to 256 so that a mutated header may ask for the most the limit allows.
#include "fuzz_sandbox.h"
#include "image/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* kExtensions[] = {".exr", ".png", ".hdr", ".tif", ".pfm", ".jpg"};
  const std::string name = std::string("fuzz") + kExtensions[data[0] % 6];
  const std::string path = tracer::fuzz::write_input(name, data + 1, size - 1);
  tracer::fuzz::expect_clean_error([&] { tracer::read_image_pixels(path, 4, 256); });
  return 0;
}
