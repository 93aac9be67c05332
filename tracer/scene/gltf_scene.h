// A glTF file's default scene (its node hierarchy) added to a Scene (docs/gltf.md): every
// TRIANGLES primitive of every mesh a node instances, through the node's world transform and
// `placement`; its materials and textures (gltf_materials.h); KHR_lights_punctual point lights;
// and its perspective cameras, for the caller to choose from. What is read but left out is
// listed in `ignored`. Errors are InputErrors naming the file and the JSON path.
#pragma once
#include <string>
#include <vector>

#include "scene/camera_setup.h"
#include "scene/gltf_file.h"
#include "scene/scene.h"
#include "scene/transform.h"

namespace tracer {

// The most triangles a glTF file may place (instancing multiplies a mesh's): checked before a
// primitive's triangles are built.
constexpr uint64_t kMaxGltfTriangles = 1ull << 24;

struct GltfCamera {
  int index;         // into the file's cameras
  std::string name;  // the camera's name, or its node's
  CameraSpec spec;   // from the node's world transform; aperture 0
  float aspect;      // width / height, 0 when the file gives none
};

struct GltfContents {
  uint32_t meshes = 0, triangles = 0, materials = 0, textures = 0, lights = 0;
  std::vector<GltfCamera> cameras;  // every perspective camera a node places, in node order
  std::vector<std::string> ignored;
};

// `with_lights`: add the file's point lights (a JSON scene that includes a glTF file brings
// its own lights and leaves them out).
GltfContents add_gltf_file(const GltfFile& file, const Transform& placement, bool with_lights, Scene& scene);

class GltfMaterials;
// The same with the file's materials kept by the caller: a file placed more than once (a JSON
// scene's gltf shapes) converts its materials and decodes and bakes its textures once (placed
// 24 times, a 1024^2 texture was stored 24 times).
GltfContents add_gltf_file(const GltfFile& file, const Transform& placement, bool with_lights, Scene& scene,
                           GltfMaterials& materials);

}  // namespace tracer
