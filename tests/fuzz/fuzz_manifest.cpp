// Fuzz target: a golden manifest (golden/golden_manifest.h) through read_manifest: names,
// scene paths that may not leave the root, options, hashes and tolerances.
#include "fuzz_sandbox.h"
#include "golden/golden_manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool made = std::filesystem::create_directories(tracer::fuzz::sandbox() / "golden");
  (void)made;
  tracer::fuzz::write_input("golden/manifest.json", data, size);
  tracer::fuzz::expect_clean_error([&] { tracer::read_manifest(tracer::fuzz::sandbox().string()); });
  return 0;
}
