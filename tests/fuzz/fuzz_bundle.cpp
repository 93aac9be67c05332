// Fuzz target: a scene bundle (bundle/scene_bundle.h) through read_scene_bundle, what
// tracer-gpu renders. The input is a bundle without its checksum, and the target appends the
// right SHA-1: a mutated byte would otherwise fail the checksum (a unit-tested refusal) and
// never reach the container's sections, the render's limits or the view's fields (settings,
// grid cells, sky table), which read_scene_bundle must check because a checksum proves only
// that the bytes are the ones written. The corpus holds real bundles less their last 20 bytes.
#include <string>

#include "bundle/scene_bundle.h"
#include "fuzz_sandbox.h"
#include "io/sha1.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  tracer::Sha1 sha;
  sha.append(bytes.data(), bytes.size());
  unsigned char digest[20];
  sha.digest(digest);
  bytes.append(reinterpret_cast<const char*>(digest), sizeof digest);
  const std::string path =
      tracer::fuzz::write_input("fuzz.bundle", reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  tracer::fuzz::expect_clean_error([&] { tracer::read_scene_bundle(path); });
  return 0;
}
