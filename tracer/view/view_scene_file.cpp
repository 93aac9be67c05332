#include "view/view_scene_file.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/input_error.h"
#include "options/number_text.h"
#include "options/render_options.h"

namespace tracer {
namespace {

// Each float as the shortest decimal that reads back to it (1.2, not 1.2000000476837158).
Json vec3_json(Vec3 v) { return Json::array({shortest_decimal(v.x), shortest_decimal(v.y), shortest_decimal(v.z)}); }

}  // namespace

Json camera_block(const CameraSpec& camera) {
  return {{"from", vec3_json(camera.from)},
          {"to", vec3_json(camera.to)},
          {"up", vec3_json(camera.up)},
          {"vfov", shortest_decimal(camera.vfov_degrees)},
          {"aperture", shortest_decimal(camera.aperture)},
          {"focus_distance", shortest_decimal(camera.focus_distance)}};
}

std::string camera_block_text(const CameraSpec& camera) { return "\"camera\": " + camera_block(camera).dump(); }

std::string scene_file_with_view(const std::string& text, const RenderSettings& settings, const CameraSpec& camera,
                                 uint32_t spp) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(text);  // it was loaded from this text
  scene["camera"] = nlohmann::ordered_json::parse(camera_block(camera).dump());
  RenderSettings saved = settings;
  saved.spp = spp;
  // An option at its default is left out (the file's way to say "off" for some), any other set.
  const nlohmann::ordered_json options = resolved_options(saved).to_json();
  const nlohmann::ordered_json defaults = resolved_options(RenderSettings{}).to_json();
  for (const OptionInfo& o : option_table()) {
    if (!options.contains(o.name)) continue;
    if (defaults.contains(o.name) && defaults[o.name] == options[o.name]) {
      if (scene.contains(o.section)) scene[o.section].erase(o.name);
    } else {
      scene[o.section][o.name] = options[o.name];
    }
  }
  return scene.dump(2) + "\n";
}

SavedNames free_save_names(const std::string& prefix) {
  for (int n = 1; n < 100000; ++n) {
    const std::string stem = prefix + "-" + std::to_string(n);
    SavedNames names{stem + ".json", stem + ".exr", stem + ".png"};
    std::error_code ec;
    if (!std::filesystem::exists(names.json, ec) && !std::filesystem::exists(names.exr, ec) &&
        !std::filesystem::exists(names.png, ec))
      return names;
  }
  throw InputError(prefix + ": no free name PREFIX-N.json for N below 100000");
}

}  // namespace tracer
