// `tracer bench variance SCENE`: where the path tracer's squared error comes from. The scene is
// rendered at --spp and, with another seed, at --ref-spp, both split by path class
// (bench/variance_split.h); each class's squared error against its own reference is printed
// beside its share of the light, largest first, then summed by estimator and by the vertices
// before the light. The reference's own noise is in every figure (at 16x the samples, about
// 6 % of it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "bench/variance_split.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "io/input_error.h"
#include "render/progress.h"
#include "scene/scene_loader.h"

namespace tracer {

struct BenchVarianceCommand {
  std::string scene;
  uint32_t spp = 64, ref_spp = 1024, width = 0, height = 0, top = 24;
  int threads = 0;
};

namespace {

struct ClassError {
  uint32_t path_class;
  double light = 0, squared_error = 0;  // sums over pixels and channels
};

SplitImages render_split_with_bar(const SceneView& view, uint32_t spp, int threads, const char* what) {
  ProgressBar bar(true);
  std::fprintf(stderr, "%s: %u spp\n", what, spp);
  SplitImages images =
      render_split(view, 0, spp, threads, [&](uint64_t done, uint64_t total) { bar.update(done, total); });
  bar.finish();
  return images;
}

void print_row(const std::string& name, double light, double total_light, double error, double total_error) {
  std::printf("%-52s %9.2f %% %12.4e %9.2f %%\n", name.c_str(), 100.0 * light / total_light, error,
              100.0 * error / total_error);
}

}  // namespace

static int run_bench_variance(const BenchVarianceCommand& cmd) {
  if (cmd.ref_spp <= cmd.spp) throw InputError("--ref-spp " + std::to_string(cmd.ref_spp) + ": must exceed --spp");
  RenderOverrides ov;
  if (cmd.width) ov.width = cmd.width;
  if (cmd.height) ov.height = cmd.height;
  const Scene scene = load_scene(cmd.scene, ov);
  if (scene.settings.integrator != IntegratorKind::Path)
    throw InputError(cmd.scene + ": render.integrator: bench variance splits the path integrator's samples");
  const SceneView view = scene.view();
  SceneView ref_view = view;
  ref_view.settings.seed = view.settings.seed ^ 0x5eed5eed5eed5eedull;  // an independent reference
  const SplitImages measured = render_split_with_bar(view, cmd.spp, cmd.threads, "measured");
  const SplitImages reference = render_split_with_bar(ref_view, cmd.ref_spp, cmd.threads, "reference");
  const size_t floats = size_t{measured.width} * measured.height * 3;
  std::vector<double> total_estimate(floats, 0.0), total_reference(floats, 0.0);
  std::vector<ClassError> classes;
  for (uint32_t c = 0; c < kPathClasses; ++c) {
    const std::vector<double>* e = measured.sums[c].get();
    const std::vector<double>* r = reference.sums[c].get();
    if (!e && !r) continue;
    ClassError ce{c};
    for (size_t i = 0; i < floats; ++i) {
      const double ei = e ? (*e)[i] / measured.samples : 0.0, ri = r ? (*r)[i] / reference.samples : 0.0;
      ce.light += ri;
      ce.squared_error += (ei - ri) * (ei - ri);
      total_estimate[i] += ei;
      total_reference[i] += ri;
    }
    classes.push_back(ce);
  }
  double light = 0, error = 0, class_error = 0;
  std::vector<double> pixel_error(floats / 3, 0.0), pixel_light(floats / 3, 0.0);
  for (size_t i = 0; i < floats; ++i) {
    const double d = total_estimate[i] - total_reference[i];
    light += total_reference[i];
    error += d * d;
    pixel_error[i / 3] += d * d;
    pixel_light[i / 3] += total_reference[i];
  }
  for (const ClassError& ce : classes) class_error += ce.squared_error;
  if (!(light > 0.0) || !(error > 0.0))
    throw InputError(cmd.scene + ": the image is black or noiseless; nothing to split");
  std::sort(classes.begin(), classes.end(),
            [](const ClassError& a, const ClassError& b) { return a.squared_error > b.squared_error; });
  const double n = static_cast<double>(floats);
  std::printf(
      "tracer bench variance %s: %ux%u, %u spp against %u (another seed); MSE per class, its share of the "
      "summed class MSE\n",
      cmd.scene.c_str(), measured.width, measured.height, measured.samples, reference.samples);
  std::printf("%-52s %11s %12s %11s\n", "class (estimator, vertices before the light, last two)", "light", "MSE",
              "error");
  double shown_light = 0, shown_error = 0;
  for (size_t i = 0; i < classes.size() && i < cmd.top; ++i) {
    print_row(path_class_name(classes[i].path_class), classes[i].light, light, classes[i].squared_error / n,
              class_error / n);
    shown_light += classes[i].light, shown_error += classes[i].squared_error;
  }
  if (classes.size() > cmd.top)
    print_row("(the other " + std::to_string(classes.size() - cmd.top) + " classes)", light - shown_light, light,
              (class_error - shown_error) / n, class_error / n);
  std::printf("\nby estimator\n");
  for (uint32_t e = 0; e < static_cast<uint32_t>(PathEstimator::kCount); ++e) {
    double l = 0, se = 0;
    for (const ClassError& ce : classes)
      if (static_cast<uint32_t>(path_class_estimator(ce.path_class)) == e) l += ce.light, se += ce.squared_error;
    print_row(path_estimator_name(static_cast<PathEstimator>(e)), l, light, se / n, class_error / n);
  }
  std::printf("\nby vertices before the light\n");
  for (uint32_t v = 0; v < kSplitBounceClasses; ++v) {
    double l = 0, se = 0;
    for (const ClassError& ce : classes)
      if (path_class_vertices(ce.path_class) == v) l += ce.light, se += ce.squared_error;
    print_row(std::to_string(v) + (v + 1 == kSplitBounceClasses ? " or more" : ""), l, light, se / n, class_error / n);
  }
  // The brightest 1 % of pixels (by the reference) and their share of the image's squared error.
  std::vector<size_t> order(pixel_light.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const size_t top = std::max<size_t>(1, order.size() / 100);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(top), order.end(),
                    [&](size_t a, size_t b) { return pixel_light[a] > pixel_light[b]; });
  double bright_error = 0;
  for (size_t i = 0; i < top; ++i) bright_error += pixel_error[order[i]];
  std::printf(
      "\nimage MSE %.4e (the classes' MSEs sum to %.3f of it; the rest is their covariance); the brightest "
      "1 %% of pixels hold %.1f %% of the image's squared error\n",
      error / n, class_error / error, 100.0 * bright_error / error);
  return 0;
}

const RegisterCommand kBenchVarianceCommand(
    {"bench", "variance", "the path tracer's squared error split by estimator, path length and the last two vertices",
     [](CLI::App& app) {
       auto cmd = std::make_shared<BenchVarianceCommand>();
       app.add_option("scene", cmd->scene, "scene file (JSON) or glTF file, path integrator")->required();
       app.add_option("--spp", cmd->spp, "samples per pixel measured (default 64)")->check(count_in(1, 1u << 16));
       app.add_option("--ref-spp", cmd->ref_spp, "the reference's samples per pixel (default 1024)")
           ->check(count_in(2, 1u << 20));
       app.add_option("--width", cmd->width, "image width (default the scene's)")->check(count_in(1, 1u << 14));
       app.add_option("--height", cmd->height, "image height (default the scene's)")->check(count_in(1, 1u << 14));
       app.add_option("--top", cmd->top, "classes listed, largest error first (default 24)")->check(count_in(1, 1000));
       add_threads_option(app, cmd->threads);
       return [cmd] { return run_bench_variance(*cmd); };
     }});

}  // namespace tracer
