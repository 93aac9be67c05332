#include "scene/scene_types.h"

#include <algorithm>

namespace tracer {

const std::map<std::string, std::vector<std::string>>& accepted_scene_types() {
  static const std::map<std::string, std::vector<std::string>> types = {
      {"shape", {"sphere", "plane", "triangle", "quad", "box", "mesh"}},
      {"material", {"lambert", "metal", "dielectric", "phong", "emissive"}},
      {"light", {"point"}},
      {"background", {"constant", "gradient", "cubemap"}},
      {"integrator", {"whitted", "normals", "albedo", "depth", "path"}},
      {"sampler", {"center", "grid", "stochastic", "stratified"}},
      {"accel", {"bvh", "none", "kdtree", "kdtree-median", "grid", "lbvh"}},
      {"texture", {"image", "checker", "specular_map", "normal_map", "bump_map"}},
      {"transform", {"translate", "scale", "rotate", "rotate_xyz"}},
  };
  return types;
}

bool is_accepted_type(const std::string& category, const std::string& name) {
  const auto& names = accepted_scene_types().at(category);
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string expected_types(const std::string& category) {
  const auto& names = accepted_scene_types().at(category);
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += names[i];
  }
  return out;
}

}  // namespace tracer
