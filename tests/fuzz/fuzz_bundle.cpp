// Fuzz target: a scene bundle (bundle/scene_bundle.h) through read_scene_bundle, what
// tracer-gpu renders: the container's sections, their sizes and the render's limits.
#include "bundle/scene_bundle.h"
#include "fuzz_sandbox.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = tracer::fuzz::write_input("fuzz.bundle", data, size);
  tracer::fuzz::expect_clean_error([&] { tracer::read_scene_bundle(path); });
  return 0;
}
