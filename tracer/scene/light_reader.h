// The scene file's `lights` entries and its `background` (docs/scene-format.md, "Lights" and
// "Background"). Emissive shapes are area lights; they are materials, not entries here.
#pragma once
#include <set>
#include <string>

#include "io/json_reader.h"
#include "kernel/scene/scene_view.h"
#include "scene/texture_loader.h"

namespace tracer {

// Records the light's type in `used_types` ("light:point").
Light read_light(const Json& value, const std::string& path, const std::string& file,
                 std::set<std::string>& used_types);

// A missing background is constant black; `type` receives its type name.
Background read_background(const Json* value, const std::string& file, std::string& type, TextureLoader& textures);

}  // namespace tracer
