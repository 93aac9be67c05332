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

// Names of feature bits set in a mask, for `tracer info` and the stats file.
std::vector<std::string> feature_names(uint32_t features);

}  // namespace tracer
