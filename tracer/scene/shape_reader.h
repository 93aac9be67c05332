// The scene file's `shapes` array as primitives (docs/scene-format.md, "Shapes"): spheres,
// planes, quads, boxes (six quads), triangles and meshes (inline or OBJ with MTL
// materials), each through its transform. Zero-area triangles of a mesh are left out and
// counted; a lone zero-area triangle or quad is an error.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "scene/scene.h"
#include "scene/texture_loader.h"

namespace tracer {

// Appends to scene.primitives (and triangle_shading, materials for MTL meshes), counts shape
// types and records used types. `material_types` is the type name of each material id.
void read_shapes(const Json& shapes, const std::string& file, const std::map<std::string, uint32_t>& material_ids,
                 const std::vector<std::string>& material_types, TextureLoader& textures, Scene& scene);

}  // namespace tracer
