// One entry of the scene file's `materials` object as a kernel Material (docs/scene-format.md,
// "Materials"): colours may be textures, maps are read through the TextureLoader.
#pragma once
#include <string>

#include "io/json_reader.h"
#include "kernel/material/material.h"
#include "scene/texture_loader.h"

namespace tracer {

// `type` receives the material's type name.
Material read_material(const Json& value, const std::string& path, const std::string& file, std::string& type,
                       TextureLoader& textures);

uint32_t material_feature(MaterialKind kind);  // its FeatureBit

}  // namespace tracer
