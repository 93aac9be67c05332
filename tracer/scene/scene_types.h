// The type names the scene loader accepts, by category (docs/scene-format.md). The loader
// rejects any name missing from these tables, and records which names a scene uses, so the
// golden coverage test can check that every accepted type is drawn by some golden.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "kernel/light/light_records.h"

namespace tracer {

// Category ("shape", "material", "light", "background", "integrator", "sampler", "accel",
// "texture": a material colour given as an image or a checker, or a map; "transform": a
// step of a shape's transform list)
// to the names the loader accepts in it, in the order docs/scene-format.md lists them.
const std::map<std::string, std::vector<std::string>>& accepted_scene_types();

bool is_accepted_type(const std::string& category, const std::string& name);

// Reads the `type` key of a section and checks it against the table of `category`.
std::string read_type(JsonObject& obj, const std::string& category);

// The declared light of a scene file's (or glTF KHR_lights_punctual's) type: "point", "spot",
// "directional"; none for any other.
std::optional<LightKind> declared_light_kind(const std::string& type);

// "sphere, plane, triangle, quad, box or mesh": for "expected ..." messages.
std::string expected_types(const std::string& category);

}  // namespace tracer
