// Loads a scene file (docs/scene-format.md, version 1) into flat arrays, applies command-line
// overrides, validates everything, computes the feature mask and builds the acceleration
// structure. Every problem is an InputError naming the file and the key path.
#pragma once
#include <string>

#include "scene/scene.h"

namespace tracer {

Scene load_scene(const std::string& path, const RenderOverrides& overrides = {});

// Parses scene text as if it were the file `path` (relative paths resolve next to it).
Scene load_scene_text(const std::string& text, const std::string& path, const RenderOverrides& overrides = {});

// A glTF file as the whole scene (docs/gltf.md): its meshes, materials, point lights and the
// camera the overrides name (or its first, or one framing its bounds); render settings from
// the overrides over the glTF defaults. `bytes` are the file's contents.
Scene load_gltf_scene(const std::string& bytes, const std::string& path, const RenderOverrides& overrides);

// The steps every scene format ends with: the feature mask, the ray offset scale, the light
// table and the acceleration structure.
void finish_scene(Scene& scene, const RenderOverrides& overrides);

// Places the camera as loading does: the kernel camera from `spec` at the film's size, and
// the ray offset scale, which counts the camera's position. For a camera moved after loading.
void place_camera(Scene& scene, const CameraSpec& spec);

// Names of feature bits set in a mask, for `tracer info` and the stats file.
std::vector<std::string> feature_names(uint32_t features);

}  // namespace tracer
