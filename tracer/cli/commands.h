// What several command files share: the render options of `render` and `bundle`, and the
// size options of the image benchmarks. Each command registers itself (command_registry.h).
#pragma once
#include <map>
#include <optional>
#include <string>

#include "cli/command_registry.h"
#include "scene/scene.h"

namespace tracer {

struct RenderCommand {
  std::string scene, output, stats;
  std::map<std::string, std::optional<std::string>> options;  // --spp 4: "spp" -> "4", for every option of the table
  int threads = 0;
  std::string device = "cpu";
  std::string samples;     // --samples A:B: write samples [A, B) to a partial file
  std::string sample_map;  // --sample-map FILE: adaptive sampling's per-pixel sample counts
  bool quiet = false;
  std::optional<std::string> camera, background;  // glTF files only
  std::optional<std::string> environment;         // any scene: an equirectangular map for its background
};

// The scene argument, one flag per option of the options table, and --samples.
void add_scene_options(CLI::App& app, RenderCommand& cmd);
RenderOverrides scene_overrides(const RenderCommand& cmd);  // the options given on the command line

// --width, --height and --threads of `bench converge` and `bench trade`.
inline void add_bench_size_options(CLI::App& app, uint32_t& width, uint32_t& height, int& threads) {
  app.add_option("--width", width, "image width override");
  app.add_option("--height", height, "image height override");
  add_threads_option(app, threads);
}

}  // namespace tracer
