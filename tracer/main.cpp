// tracer: render, inspect and compare. Exit codes: 0 success, 1 comparison failed,
// 2 bad input (the message names the file and key) or any other error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "commands.h"
#include "input_error.h"

int main(int argc, char** argv) {
  using namespace tracer;
  CLI::App app{"tracer: a deterministic ray tracer"};
  app.require_subcommand(1);

  RenderCommand render;
  CLI::App* r = app.add_subcommand("render", "render a scene to an image");
  r->add_option("scene", render.scene, "scene file (JSON)")->required();
  r->add_option("-o,--output", render.output, "output image (.exr linear float, .png sRGB, ...); default SCENE.png");
  r->add_option("--spp", render.overrides.spp, "samples per pixel");
  r->add_option("--seed", render.overrides.seed, "64-bit seed");
  r->add_option("--width", render.overrides.width, "image width in pixels");
  r->add_option("--height", render.overrides.height, "image height in pixels");
  r->add_option("--integrator", render.overrides.integrator, "whitted, normals, albedo or depth");
  r->add_option("--max-depth", render.overrides.max_depth, "maximum ray depth");
  r->add_option("--sampler", render.overrides.sampler, "center, grid, stochastic or stratified");
  r->add_option("--accel", render.overrides.accel, "bvh or none");
  r->add_option("--threads", render.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);
  r->add_option("--device", render.device, "cpu or cuda");
  r->add_option("--stats", render.stats, "write timings and ray counts as JSON");
  r->add_flag("--quiet", render.quiet, "no progress bar or summary");

  std::string info_scene;
  CLI::App* i = app.add_subcommand("info", "primitive counts, feature mask and acceleration stats");
  i->add_option("scene", info_scene, "scene file (JSON)")->required();

  CompareCommand compare;
  CLI::App* c = app.add_subcommand("compare", "compare two images (idiff semantics)");
  c->add_option("a", compare.a, "first image")->required();
  c->add_option("b", compare.b, "second image")->required();
  c->add_option("--fail", compare.options.fail, "per-channel failure threshold; 0 means bit-exact");
  c->add_option("--failpercent", compare.options.failpercent, "percentage of pixels allowed to fail");
  c->add_option("--warn", compare.options.warn, "per-channel warning threshold");
  c->add_option("--warnpercent", compare.options.warnpercent, "percentage of pixels allowed to warn");
  c->add_option("--diff", compare.diff, "write |a - b| to this image");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*r) return run_render(render);
    if (*i) return run_info(info_scene);
    return run_compare(compare);
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return 2;
}
