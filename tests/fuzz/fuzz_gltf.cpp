// Fuzz target: a glTF file through the whole glTF reader (docs/gltf.md): the checked JSON
// parse and schema, tinygltf, accessors, nodes, materials, textures, cameras and lights, and
// the acceleration structure, as `tracer render FILE.glb` loads it. The input is written as
// sandbox()/model.glb (text inputs are read as .gltf: the reader looks at the first bytes).
#include "fuzz_sandbox.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = tracer::fuzz::write_input("model.glb", data, size);
  tracer::RenderOverrides small;
  small.width = 4;
  tracer::fuzz::expect_clean_error([&] { tracer::load_scene(path, small); });
  return 0;
}
