// Fuzz target: an MTL file, read for a one-triangle OBJ by the scene loader and mapped onto our
// materials with its texture maps (scene/mtl_materials.h). The MTL lies in sandbox()/models, so
// map names like ../textures/tiles.png resolve as in scenes/models/crate.mtl.
#include <cstring>

#include "fuzz_sandbox.h"
#include "scene/scene_loader.h"

namespace {

const char kObj[] = "mtllib fuzz.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl fuzz\nf 1/1 2/2 3/3\n";
const char kScene[] = R"({"format": "tracer-scene/1",
  "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40}, "film": {"width": 4, "height": 4},
  "materials": {}, "lights": [{"type": "point", "position": [0, 2, 2], "intensity": [5, 5, 5]}],
  "shapes": [{"type": "mesh", "file": "models/mtl-fuzz.obj"}]})";

const std::string& scene_path() {
  static const std::string path = [] {
    tracer::fuzz::write_input("models/mtl-fuzz.obj", reinterpret_cast<const uint8_t*>(kObj), std::strlen(kObj));
    return tracer::fuzz::write_input("mtl-scene.json", reinterpret_cast<const uint8_t*>(kScene), std::strlen(kScene));
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string& scene = scene_path();
  tracer::fuzz::write_input("models/fuzz.mtl", data, size);
  tracer::fuzz::expect_clean_error([&] { tracer::load_scene(scene); });
  return 0;
}
