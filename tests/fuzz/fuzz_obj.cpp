// Fuzz target: an OBJ file through load_obj (our strict statement check, then tinyobjloader),
// with its MTL materials requested, as a scene's mesh without a "material" reads it.
#include "fuzz_sandbox.h"
#include "scene/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = tracer::fuzz::write_input("models/fuzz.obj", data, size);
  std::vector<tracer::MtlMaterial> materials;
  tracer::fuzz::expect_clean_error([&] { tracer::load_obj(path, "fuzz.json", "shapes[0].file", &materials); });
  return 0;
}
