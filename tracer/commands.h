// The CLI's subcommands; each returns the process exit code (0 ok, 1 comparison failed,
// 2 bad input or error). main.cpp parses the command line with CLI11.
#pragma once
#include <string>

#include "compare.h"
#include "scene.h"

namespace tracer {

struct RenderCommand {
  std::string scene, output, stats;
  RenderOverrides overrides;
  int threads = 0;
  std::string device = "cpu";
  bool quiet = false;
};

struct CompareCommand {
  std::string a, b, diff;
  CompareOptions options;
};

int run_render(const RenderCommand& cmd);
int run_info(const std::string& scene_path);
int run_compare(const CompareCommand& cmd);

}  // namespace tracer
