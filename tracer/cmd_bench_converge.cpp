// `tracer bench converge SCENE --spp 1,4,16,...`: error against time as the sample count
// grows, for the scene's settings or for NEE+MIS and the plain estimator side by side; a
// table, a CSV file and a log-log plot of RMSE against seconds.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "bench_common.h"
#include "commands.h"
#include "input_error.h"
#include "loglog_plot.h"
#include "scene_loader.h"

namespace tracer {
namespace {

struct Point {
  uint32_t spp;
  double seconds;
  ImageError error;
};

// Seconds the series needs for `rmse`, interpolated in log-log between its points, or
// extrapolated from its last point along the 1/sqrt(time) law; `extrapolated` says which.
double seconds_to_reach(const std::vector<Point>& series, double rmse, bool& extrapolated) {
  extrapolated = false;
  for (size_t i = 1; i < series.size(); ++i) {
    const Point &a = series[i - 1], &b = series[i];
    if (b.error.rmse <= rmse && a.error.rmse >= rmse) {
      const double f = (std::log(rmse) - std::log(a.error.rmse)) / (std::log(b.error.rmse) - std::log(a.error.rmse));
      return std::exp(std::log(a.seconds) + f * (std::log(b.seconds) - std::log(a.seconds)));
    }
  }
  extrapolated = true;
  const Point& last = series.back();
  return last.seconds * (last.error.rmse / rmse) * (last.error.rmse / rmse);
}

}  // namespace

int run_bench_converge(const BenchConvergeCommand& cmd) {
  const std::vector<uint32_t> spps = parse_spp_list("--spp", cmd.spp);
  if (cmd.nee != "scene" && cmd.nee != "on" && cmd.nee != "off" && cmd.nee != "both")
    throw InputError("--nee " + cmd.nee + ": expected scene, on, off or both");
  const std::string stem = std::filesystem::path(cmd.scene).stem().string();
  const std::string csv = cmd.csv.empty() ? stem + "-converge.csv" : cmd.csv;
  const std::string plot = cmd.plot.empty() ? stem + "-converge.png" : cmd.plot;
  RenderOverrides base;
  if (cmd.width) base.width = cmd.width;
  if (cmd.height) base.height = cmd.height;
  if (cmd.nee == "on" || cmd.nee == "both") base.nee = true;
  if (cmd.nee == "off") base.nee = false;
  uint32_t max_spp = 0;
  for (uint32_t s : spps) max_spp = std::max(max_spp, s);
  const Scene probe = load_scene(cmd.scene, base);
  if (probe.settings.sampler == SamplerKind::Center && max_spp > 1)
    base.sampler = "stochastic";  // the center sampler takes one sample only
  std::printf("tracer bench converge %s: %ux%u, %s\n", cmd.scene.c_str(), probe.settings.width, probe.settings.height,
              cmd.nee == "both" ? "NEE+MIS and the plain estimator" : "the scene's estimator");
  const Image ref = reference_image(cmd.scene, base, cmd.ref, cmd.ref_spp ? cmd.ref_spp : 8 * max_spp, cmd.threads);

  std::vector<std::pair<std::string, bool>> series_setups;
  if (cmd.nee == "both") series_setups = {{"NEE+MIS", true}, {"plain", false}};
  else series_setups = {{probe.settings.integrator == IntegratorKind::Path ? (probe.settings.nee ? "NEE+MIS" : "plain") : "render", probe.settings.nee != 0}};

  std::ofstream out(csv);
  if (!out) throw InputError(csv + ": cannot write");
  out << "series,spp,seconds,rmse,rel_mse\n";
  std::printf("%-10s %8s %10s %12s %12s\n", "series", "spp", "seconds", "RMSE", "relMSE");
  std::vector<std::vector<Point>> results;
  std::vector<PlotSeries> lines;
  for (const auto& [label, nee] : series_setups) {
    RenderOverrides ov = base;
    if (cmd.nee == "both") ov.nee = nee;
    results.emplace_back();
    PlotSeries line{label, {}, {}};
    for (uint32_t spp : spps) {
      ov.spp = spp;
      const TimedRender r = timed_render(load_scene(cmd.scene, ov), cmd.threads);
      const ImageError e = image_error(r.image, ref);
      results.back().push_back({spp, r.seconds, e});
      line.x.push_back(r.seconds);
      line.y.push_back(e.rmse);
      std::printf("%-10s %8u %10.3f %12.6g %12.6g\n", label.c_str(), spp, r.seconds, e.rmse, e.rel_mse);
      out << label << "," << spp << "," << r.seconds << "," << e.rmse << "," << e.rel_mse << "\n";
    }
    lines.push_back(line);
  }
  out.close();
  if (!out) throw InputError(csv + ": cannot write");
  write_loglog_plot(plot, {"RMSE against render time: " + stem, "seconds", "RMSE"}, lines);
  if (results.size() == 2) {
    const Point& plain = results[1].back();
    bool extrapolated = false;
    const double t = seconds_to_reach(results[0], plain.error.rmse, extrapolated);
    std::printf("NEE+MIS reaches the plain estimator's RMSE at %u spp (%.6g, %.3f s) in %.3f s%s: %.1fx less time\n",
                plain.spp, plain.error.rmse, plain.seconds, t, extrapolated ? " (extrapolated as 1/sqrt(time))" : "",
                plain.seconds / t);
  }
  std::printf("wrote %s and %s\n", std::filesystem::absolute(csv).string().c_str(),
              std::filesystem::absolute(plot).string().c_str());
  return 0;
}

}  // namespace tracer
