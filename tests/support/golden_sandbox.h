// A throwaway source root for testing the golden checker: ROOT/scenes/{ball,box}.json
// and ROOT/golden/manifest.json with goldens "ball" and "box", made by the real update
// command (forced: the sandbox is not a git checkout).
#pragma once
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "golden/golden_update.h"
#include "test_util.h"

namespace tracer::test {

inline std::string sandbox_scene(const std::string& shape) {
  return R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 1, 4], "to": [0, 0.5, 0], "vfov": 40},
    "film": {"width": 24, "height": 16},
    "render": {"integrator": "whitted", "spp": 1, "sampler": "center", "max_depth": 2},
    "background": {"type": "constant", "radiance": [0.1, 0.1, 0.2]},
    "ambient": [0.05, 0.05, 0.05],
    "materials": {"white": {"type": "lambert", "albedo": [0.8, 0.8, 0.8]},
                  "red": {"type": "lambert", "albedo": [0.8, 0.1, 0.1]}},
    "lights": [{"type": "point", "position": [2, 4, 3], "intensity": [30, 30, 30]}],
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"}, )" +
         shape + "]}";
}

inline const char* kSandboxBall = R"({"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "red"})";
inline const char* kSandboxBox = R"({"type": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5], "material": "red"})";

struct GoldenSandbox {
  std::filesystem::path root;

  explicit GoldenSandbox(const std::string& name) : root(temp_dir("golden-" + name)) {
    std::filesystem::create_directories(root / "scenes");
    std::filesystem::create_directories(root / "golden");
    write("scenes/ball.json", sandbox_scene(kSandboxBall));
    write("scenes/box.json", sandbox_scene(kSandboxBox));
    write("golden/manifest.json", R"({"format": "tracer-golden/1", "goldens": {
        "ball": {"scene": "scenes/ball.json"}, "box": {"scene": "scenes/box.json"}}})");
    UpdateRequest request;
    request.root = root.string();
    request.force = true;
    update_goldens(request);
  }
  ~GoldenSandbox() { std::filesystem::remove_all(root); }

  void write(const std::string& rel, const std::string& text) const {
    std::ofstream(root / rel, std::ios::binary) << text;
  }
  std::string read(const std::string& rel) const {
    std::stringstream s;
    s << std::ifstream(root / rel, std::ios::binary).rdbuf();
    return s.str();
  }
  // Every file under golden/ with its bytes, to prove a command left them alone.
  std::map<std::string, std::string> golden_files() const {
    std::map<std::string, std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(root / "golden"))
      files[e.path().filename().string()] = read("golden/" + e.path().filename().string());
    return files;
  }
  void move_ball() const {
    write("scenes/ball.json",
          sandbox_scene(R"({"type": "sphere", "center": [0.1, 0.5, 0], "radius": 0.5, "material": "red"})"));
  }
  // Arguments of `tracer golden check` for one golden of the sandbox.
  std::string check_args(const std::string& name, const std::string& report = "") const {
    return "golden check " + name + " --root " + root.string() + (report.empty() ? "" : " --report " + report);
  }
};

}  // namespace tracer::test
