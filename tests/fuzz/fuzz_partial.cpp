// Fuzz target: a partial-render file (render/partial_file.h) through read_partial, which `tracer
// merge` trusts only after checking every header number, the size, the SHA-1 and each sum.
#include "fuzz_sandbox.h"
#include "render/partial_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = tracer::fuzz::write_input("fuzz.partial", data, size);
  tracer::fuzz::expect_clean_error([&] { tracer::read_partial(path); });
  return 0;
}
