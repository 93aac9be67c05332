// tracer: render, inspect, compare and check goldens. Exit codes: 0 success, 1 comparison failed,
// 2 bad input (the message names the file and key) or any other error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cli/commands.h"

namespace {

// The options every speed/accuracy benchmark takes.
void add_bench_size_options(CLI::App* app, uint32_t& width, uint32_t& height, int& threads) {
  app->add_option("--width", width, "image width override");
  app->add_option("--height", height, "image height override");
  app->add_option("--threads", threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);
}


// The options that decide what a render computes: `render` and `bundle` share them.
void add_scene_options(CLI::App* app, tracer::RenderCommand& cmd) {
  app->add_option("scene", cmd.scene, "scene file (JSON)")->required();
  for (const tracer::OptionInfo& o : tracer::option_table()) app->add_option(tracer::option_flag(o.name), cmd.options[o.name], o.help);
  app->add_option("--samples", cmd.samples, "A:B renders only samples [A, B) of every pixel (render: into NAME.partial, for tracer merge)");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tracer;
  CLI::App app{"tracer: a deterministic ray tracer"};
  app.require_subcommand(1);

  RenderCommand render;
  CLI::App* r = app.add_subcommand("render", "render a scene to an image");
  add_scene_options(r, render);
  r->add_option("-o,--output", render.output, "output image (.exr linear float, .png sRGB, ...); default SCENE.png");
  r->add_option("--threads", render.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);
  r->add_option("--device", render.device, "cpu or cuda");
  r->add_option("--stats", render.stats, "write timings and ray counts as JSON");
  r->add_flag("--quiet", render.quiet, "no progress bar or summary");

  RenderCommand bundle;
  CLI::App* bu = app.add_subcommand("bundle", "write what the kernel reads for one render as a scene bundle for tracer-gpu");
  add_scene_options(bu, bundle);
  bu->add_option("-o,--output", bundle.output, "output bundle, NAME.bundle")->required();

  GpuPackCommand pack;
  CLI::App* gp = app.add_subcommand("gpu-pack", "write the GPU pack: golden bundles, parity cases, tracer-gpu and run.sh");
  gp->add_option("dir", pack.dir, "new directory to create")->required();
  gp->add_option("--root", pack.root, "source root holding golden/ and scenes/ (default .)");
  gp->add_option("--runner", pack.runner, "tracer-gpu binary to include (default: beside this tracer)");
  gp->add_option("--threads", pack.threads, "CPU threads for the parity answers (default: all)")->check(CLI::NonNegativeNumber);

  MergeCommand merge;
  CLI::App* m = app.add_subcommand("merge", "add partial renders (--samples) into the image of all their samples");
  m->add_option("parts", merge.parts, "partial files of one render covering samples [0, spp) once")->required();
  m->add_option("-o,--output", merge.output, "output image (.exr, .png, ...)")->required();

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

  CLI::App* g = app.add_subcommand("golden", "golden-image regression checks (docs/golden.md)");
  g->require_subcommand(1);
  GoldenCheckCommand check;
  CLI::App* gc = g->add_subcommand("check", "render one golden and compare it bit for bit with its reference");
  gc->add_option("name", check.name, "golden name (golden/manifest.json)")->required();
  gc->add_option("--root", check.root, "source root holding golden/ and scenes/ (default .)");
  gc->add_option("--report", check.report, "report directory: writes a row, and images on a difference");
  gc->add_option("--threads", check.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);
  gc->add_option("--device", check.device, "cpu or cuda; exit 77 (skipped) when the device is missing");
  UpdateRequest update;
  CLI::App* gu = g->add_subcommand("update", "rewrite the goldens that are new or differ, print what changed");
  gu->add_option("--root", update.root, "source root holding golden/ and scenes/ (default .)");
  gu->add_option("--filter", update.filter, "only goldens whose name matches this regular expression");
  gu->add_flag("--force", update.force, "run even when golden/ has uncommitted edits");
  gu->add_option("--threads", update.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);
  GoldenReportCommand report;
  CLI::App* gr = g->add_subcommand("report", "assemble the HTML report from the rows the checks wrote");
  gr->add_option("--report", report.report, "report directory")->required();
  gr->add_flag("--reset", report.reset, "remove all rows and images instead");
  std::string list_root = ".";
  CLI::App* gl = g->add_subcommand("list", "print the golden names, one per line");
  gl->add_option("--root", list_root, "source root holding golden/ (default .)");

  CLI::App* b = app.add_subcommand("bench", "benchmarks: speed against a baseline measured in the same run");
  b->require_subcommand(1);
  BenchDeviceCommand bench_device;
  CLI::App* bd = b->add_subcommand("device", "Whitted frames/s and Mrays/s on a device: per effect, per resolution");
  bd->add_option("--device", bench_device.device, "cuda (default; the CPU is timed too, as the baseline) or cpu");
  bd->add_option("--frames", bench_device.frames, "frames per measurement; the median is reported (default 5)");
  bd->add_option("--scenes", bench_device.scenes, "scene directory: cornell-box.json and the mesh scenes (default scenes)");
  bd->add_option("--threads", bench_device.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);

  BenchConvergeCommand converge;
  CLI::App* bc = b->add_subcommand("converge", "RMSE and relMSE against time as spp grows; CSV and a log-log plot");
  bc->add_option("scene", converge.scene, "scene file (JSON)")->required();
  bc->add_option("--spp", converge.spp, "comma-separated sample counts (default 1,4,16,64,256)");
  bc->add_option("--nee", converge.nee, "scene (default), on, off, or both: NEE+MIS and the plain estimator side by side");
  bc->add_option("--ref", converge.ref, "reference image (EXR); default: render one at --ref-spp");
  bc->add_option("--ref-spp", converge.ref_spp, "reference samples per pixel (default 8 x the largest --spp)");
  bc->add_option("--csv", converge.csv, "table output (default SCENE-converge.csv)");
  bc->add_option("--plot", converge.plot, "log-log plot of RMSE against seconds (default SCENE-converge.png)");
  add_bench_size_options(bc, converge.width, converge.height, converge.threads);
  BenchTradeCommand trade;
  CLI::App* bt = b->add_subcommand("trade", "time and error of each knob, at a fixed sample budget and at equal time");
  bt->add_option("scene", trade.scene, "scene file (JSON)")->required();
  bt->add_option("--spp", trade.spp, "the fixed sample budget (default 64)");
  bt->add_option("--ref", trade.ref, "reference image (EXR); default: render one at --ref-spp");
  bt->add_option("--ref-spp", trade.ref_spp, "reference samples per pixel (default 16 x --spp)");
  add_bench_size_options(bt, trade.width, trade.height, trade.threads);

  BenchRaysCommand bench_rays;
  CLI::App* br = b->add_subcommand("rays", "build time, memory and Mrays/s of each acceleration structure");
  br->add_option("scene", bench_rays.scene, "scene file (JSON) or OBJ mesh")->required();
  br->add_option("--accel", bench_rays.accel, "comma-separated structures (default bvh,lbvh,kdtree,kdtree-median,grid)");
  br->add_option("--rays", bench_rays.incoherent, "incoherent rays (default 2^22)");
  br->add_option("--grid-resolution", bench_rays.grid_resolution, "grid cells along the longest axis (default: by density)");
  br->add_option("--threads", bench_rays.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);

  BenchWatertightCommand watertight;
  CLI::App* bw = b->add_subcommand("watertight", "rays that escape closed meshes through cracks: watertight test vs Moller-Trumbore");
  bw->add_option("meshes", watertight.meshes, "closed OBJ meshes (default: a generated icosphere and cube, and scenes/generated/bunny.obj)");
  bw->add_option("--edge-points", watertight.edge_points, "points aimed at along every edge (default 16)");
  bw->add_option("--threads", watertight.threads, "CPU threads (default: all)")->check(CLI::NonNegativeNumber);

  GenerateCommand generate;
  CLI::App* gen = app.add_subcommand("generate", "write a deterministic procedural mesh as OBJ");
  gen->add_option("kind", generate.kind, "terrain, sphere, boxes, cubes, mixed, icosphere or cube")->required();
  gen->add_option("--triangles", generate.triangles, "target triangle count (default 100000)");
  gen->add_option("-o,--output", generate.output, "OBJ file")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*r) return run_render(render);
    if (*bu) return run_bundle(bundle);
    if (*gp) return run_gpu_pack(pack);
    if (*i) return run_info(info_scene);
    if (*m) return run_merge(merge);
    if (*gc) return run_golden_check(check);
    if (*gu) return run_golden_update(update);
    if (*gr) return run_golden_report(report);
    if (*gl) return run_golden_list(list_root);
    if (*bd) return run_bench_device(bench_device);
    if (*bc) return run_bench_converge(converge);
    if (*bt) return run_bench_trade(trade);
    if (*br) return run_bench_rays(bench_rays);
    if (*bw) return run_bench_watertight(watertight);
    if (*gen) return run_generate(generate);
    return run_compare(compare);
  } catch (const std::exception& e) {  // InputError, DeviceUnavailable, CUDA errors, I/O
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return 2;
}
