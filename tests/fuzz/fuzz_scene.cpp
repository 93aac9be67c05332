// Fuzz target: a scene file through the whole loader (JSON, materials, shapes, lights, meshes,
// textures, the acceleration structure), as `tracer render` loads it. The input is written as
// sandbox()/scene.json, beside copies of scenes/models and scenes/textures.
#include "fuzz_sandbox.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = tracer::fuzz::write_input("scene.json", data, size);
  tracer::fuzz::expect_clean_error([&] { tracer::load_scene(path); });
  return 0;
}
