#include "scene/scene_types.h"

#include <algorithm>
#include <iterator>

#include "options/enum_names.h"

namespace tracer {

namespace {

template <class E>
std::vector<std::string> names_of() {
  return {std::begin(EnumNames<E>::names), std::end(EnumNames<E>::names)};
}

}  // namespace

const std::map<std::string, std::vector<std::string>>& accepted_scene_types() {
  static const std::map<std::string, std::vector<std::string>> types = {
      {"shape", {"sphere", "plane", "triangle", "quad", "box", "mesh", "gltf"}},
      {"material", names_of<MaterialKind>()},
#define TRACER_DECLARED_LIGHT_TYPE(Kind, type) type,
      {"light", {TRACER_DECLARED_LIGHT_KINDS(TRACER_DECLARED_LIGHT_TYPE)}},
#undef TRACER_DECLARED_LIGHT_TYPE
      {"background", names_of<BackgroundKind>()},
      {"integrator", names_of<IntegratorKind>()},
      {"sampler", names_of<SamplerKind>()},
      {"accel", names_of<AccelKind>()},
      {"texture", {"image", "checker", "specular_map", "normal_map", "bump_map", "metal_rough_map", "alpha_map"}},
      {"alpha", {"mask", "blend"}},
      {"transform", {"translate", "scale", "rotate", "rotate_xyz"}},
  };
  return types;
}

std::optional<LightKind> declared_light_kind(const std::string& type) {
#define TRACER_DECLARED_LIGHT_OF_TYPE(Kind, name) \
  if (type == name) return LightKind::Kind;
  TRACER_DECLARED_LIGHT_KINDS(TRACER_DECLARED_LIGHT_OF_TYPE)
#undef TRACER_DECLARED_LIGHT_OF_TYPE
  return std::nullopt;
}

bool is_accepted_type(const std::string& category, const std::string& name) {
  const auto& names = accepted_scene_types().at(category);
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string expected_types(const std::string& category) { return name_list(accepted_scene_types().at(category)); }

std::string read_type(JsonObject& obj, const std::string& category) {
  const std::string type = obj.string("type");
  if (!is_accepted_type(category, type))
    obj.fail("type", "unknown " + category + " type \"" + type + "\" (expected " + expected_types(category) + ")");
  return type;
}

}  // namespace tracer
