// `tracer bench converge SCENE --spp 1,4,16,...`: error against time as the sample count
// grows, for the scene's settings, for NEE+MIS and the plain estimator side by side, for
// several samplers or several configurations of render options side by side; a table, a CSV
// file and a log-log plot of RMSE against seconds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

#include "bench/bench_common.h"
#include "bench/loglog_plot.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "image/image_io.h"
#include "io/input_error.h"
#include "io/output_paths.h"
#include "options/enum_names.h"
#include "options/render_options.h"
#include "scene/scene_loader.h"

namespace tracer {

struct BenchConvergeCommand {
  std::string scene, ref, csv, plot, spp = "1,4,16,64,256", nee = "scene", samplers, configs, thresholds;
  uint32_t ref_spp = 0, width = 0, height = 0, min_spp = 0, adaptive_spp = 0;
  int threads = 0;
};
namespace {

struct Series {
  std::string label;
  RenderOverrides overrides;  // on top of the common ones
};

struct Point {
  uint32_t spp;
  double seconds;
  ImageError error;
};

// Seconds the series needs to bring `metric` down to `target`, interpolated in log-log
// between its points, or extrapolated from its last point along the error ~ 1/sqrt(time)
// law (`power` 1 for an RMSE, 2 for a mean squared error); `extrapolated` says which.
double seconds_to_reach(const std::vector<Point>& series, double ImageError::*metric, double power, double target,
                        bool& extrapolated) {
  extrapolated = false;
  if (series.front().error.*metric <= target) {  // already there at the first point: scale back from it
    extrapolated = true;
    return series.front().seconds * std::pow(series.front().error.*metric / target, 2.0 / power);
  }
  for (size_t i = 1; i < series.size(); ++i) {
    const double a = series[i - 1].error.*metric, b = series[i].error.*metric;
    if (b <= target && a >= target) {
      const double f = (std::log(target) - std::log(a)) / (std::log(b) - std::log(a));
      return std::exp(std::log(series[i - 1].seconds) +
                      f * (std::log(series[i].seconds) - std::log(series[i - 1].seconds)));
    }
  }
  extrapolated = true;
  const Point& last = series.back();
  return last.seconds * std::pow(last.error.*metric / target, 2.0 / power);
}

// The error metrics compared between series; `power` 1 for an RMSE, 2 for a mean squared error.
const struct {
  const char* name;
  double ImageError::*metric;
  double power;
} kMetrics[] = {{"RMSE", &ImageError::rmse, 1},
                {"display RMSE", &ImageError::display_rmse, 1},
                {"relMSE", &ImageError::rel_mse, 2}};

// A CSV field (RFC 4180): quoted, quotes doubled, when it holds a comma or a quote.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// `--configs "rr_depth=3;rr_depth=65,nee=off"`: one series per configuration, each a set of
// render options by their scene keys. spp, width and height are the command's own.
std::vector<Series> parse_configs(const std::string& text) {
  std::vector<Series> configs;
  std::stringstream list(text);
  for (std::string config; std::getline(list, config, ';');) {
    const std::string context = "--configs \"" + config + "\": ";
    if (config.empty()) throw InputError("--configs \"" + text + "\": an empty configuration");
    Series series{config, {}};
    std::stringstream pairs(config);
    for (std::string pair; std::getline(pairs, pair, ',');) {
      const size_t eq = pair.find('=');
      const std::string key = pair.substr(0, eq);
      if (eq == std::string::npos || key.empty())
        throw InputError(context + "expected KEY=VALUE, not \"" + pair + "\"");
      if (key == "spp" || key == "width" || key == "height")
        throw InputError(context + key + " is the command's own (--" + key + "), not a configuration's");
      parse_option_text(key, pair.substr(eq + 1), context, series.overrides);
    }
    configs.push_back(series);
  }
  if (configs.size() < 2) throw InputError("--configs: give two or more configurations, separated by ';'");
  return configs;
}

// Series i against series 0 (the first sampler or configuration listed): RMSE at each equal spp as a ratio,
// and the time series i needs to reach series 0's RMSE at its largest spp.
void compare_with_baseline(const std::vector<Series>& setups, const std::vector<std::vector<Point>>& results,
                           size_t i) {
  const std::string& name = setups[i].label;
  const std::string& base_name = setups[0].label;
  std::printf("%s against %s, RMSE at equal spp:", name.c_str(), base_name.c_str());
  for (size_t k = 0; k < results[i].size(); ++k)
    std::printf(" %u spp %.3fx%s", results[i][k].spp, results[i][k].error.rmse / results[0][k].error.rmse,
                k + 1 < results[i].size() ? "," : "\n");
  const Point& last = results[0].back();
  bool extrapolated = false;
  const double t = seconds_to_reach(results[i], &ImageError::rmse, 1, last.error.rmse, extrapolated);
  std::printf("%s reaches %s's RMSE at %u spp (%.6g, %.3f s) in %.3f s%s: time to equal RMSE %.3fx\n", name.c_str(),
              base_name.c_str(), last.spp, last.error.rmse, last.seconds, t, extrapolated ? " (extrapolated)" : "",
              t / last.seconds);
}

}  // namespace

static int run_bench_converge(const BenchConvergeCommand& cmd) {
  const std::vector<uint32_t> spps = parse_spp_list("--spp", cmd.spp);
  if (cmd.nee != "scene" && cmd.nee != "on" && cmd.nee != "off" && cmd.nee != "both")
    throw InputError("--nee " + cmd.nee + ": expected scene, on, off or both");
  const std::vector<SamplerKind> samplers = parse_enum_list<SamplerKind>(cmd.samplers, "--samplers");
  if (!samplers.empty() && cmd.nee == "both")
    throw InputError("--samplers: compares samplers with one estimator; give --nee scene, on or off with it");
  if (samplers.size() == 1) throw InputError("--samplers: give two or more samplers to compare");
  const std::vector<Series> configs = cmd.configs.empty() ? std::vector<Series>{} : parse_configs(cmd.configs);
  if (!configs.empty() && (cmd.nee == "both" || !samplers.empty()))
    throw InputError("--configs: compares configurations alone; give it without --samplers or --nee both");
  std::vector<float> thresholds;
  std::stringstream threshold_texts(cmd.thresholds);
  for (std::string text; std::getline(threshold_texts, text, ',');) {
    RenderOptions o;
    parse_option_text("noise_threshold", text, "--thresholds: ", o);
    thresholds.push_back(*o.noise_threshold);
  }
  if (!thresholds.empty() && (cmd.nee == "both" || !samplers.empty() || !configs.empty()))
    throw InputError(
        "--thresholds: compares adaptive with uniform sampling alone; give it without --samplers, --configs or "
        "--nee both");
  const std::string stem = std::filesystem::path(cmd.scene).stem().string();
  const std::string csv = cmd.csv.empty() ? stem + "-converge.csv" : cmd.csv;
  const std::string plot = cmd.plot.empty() ? stem + "-converge.png" : cmd.plot;
  RenderOverrides base;
  if (cmd.width) base.width = cmd.width;
  if (cmd.height) base.height = cmd.height;
  if (cmd.nee == "on" || cmd.nee == "both") base.nee = Switch::On;
  if (cmd.nee == "off") base.nee = Switch::Off;
  uint32_t max_spp = 0;
  for (uint32_t s : spps) max_spp = std::max(max_spp, s);
  const Scene probe = load_scene(cmd.scene, base);
  check_output_location(csv, "--csv");
  check_image_output(plot, "--plot");
  std::vector<std::string> inputs = probe.files_read();
  inputs.push_back(cmd.ref);
  refuse_outputs_naming_inputs(
      {{csv, "--csv"}, {plot, "--plot"}, {cmd.ref.empty() ? stem + "-converge-ref.exr" : "", "the reference cache"}},
      inputs);
  // The center sampler takes one sample only.
  if (probe.settings.sampler == SamplerKind::Center && max_spp > 1) base.sampler = SamplerKind::Stochastic;
  std::sort(thresholds.begin(), thresholds.end(), std::greater<float>());  // cheapest first
  RenderOverrides adaptive = base;
  adaptive.spp = cmd.adaptive_spp ? cmd.adaptive_spp : 4 * max_spp;
  if (cmd.min_spp) adaptive.min_spp = cmd.min_spp;
  // The adaptive series' settings (a sampler adaptive sampling cannot use, --min-spp above the
  // series' spp) are refused here, not after the reference and the uniform series rendered.
  if (!thresholds.empty()) {
    adaptive.noise_threshold = thresholds.front();
    load_scene(cmd.scene, adaptive);
  }
  // Each configuration loads at every spp of the list before the reference renders (checked at
  // the largest alone, one was refused after rows were printed), its refusal naming it.
  for (const Series& config : configs)
    for (const uint32_t spp : spps) {
      RenderOverrides ov = base;
      ov.override_with(config.overrides);
      ov.spp = spp;
      ov.origin = "--configs \"" + config.label + "\"";  // refusals name it, not a flag
      try {
        load_scene(cmd.scene, ov);
      } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + " (at --spp " + std::to_string(spp) + ")");
      }
    }
  std::printf("tracer bench converge %s: %ux%u, %s\n", cmd.scene.c_str(), probe.settings.width, probe.settings.height,
              cmd.nee == "both" ? "NEE+MIS and the plain estimator" : "the scene's estimator");
  const Image ref = reference_image(cmd.scene, base, cmd.ref, cmd.ref_spp ? cmd.ref_spp : 8ull * max_spp, cmd.threads,
                                    stem + "-converge-ref.exr");

  const bool nee = probe.settings.nee == Switch::On;
  std::vector<Series> series_setups;
  if (cmd.nee == "both") {
    series_setups = {{"NEE+MIS", {}}, {"plain", {}}};
    series_setups[0].overrides.nee = Switch::On;
    series_setups[1].overrides.nee = Switch::Off;
  } else if (!samplers.empty()) {
    for (SamplerKind kind : samplers) {
      series_setups.push_back({enum_name(kind), {}});
      series_setups.back().overrides.sampler = kind;
    }
  } else if (!configs.empty()) {
    series_setups = configs;
  } else {
    series_setups = {{probe.settings.integrator == IntegratorKind::Path ? (nee ? "NEE+MIS" : "plain") : "render", {}}};
  }

  std::ostringstream out;  // the table, written with the plot once every render is done
  out << "series,spp,seconds,rmse,display_rmse,rel_mse\n";
  int label_width = 10;
  for (const Series& series : series_setups) label_width = std::max(label_width, static_cast<int>(series.label.size()));
  std::printf("%-*s %8s %10s %12s %13s %12s\n", label_width, "series", "spp", "seconds", "RMSE", "display RMSE",
              "relMSE");
  std::vector<std::vector<Point>> results;
  std::vector<PlotSeries> lines;
  for (const auto& [label, overrides] : series_setups) {
    RenderOverrides ov = base;
    ov.override_with(overrides);
    results.emplace_back();
    PlotSeries line{label, {}, {}};
    for (uint32_t spp : spps) {
      ov.spp = spp;
      const TimedRender r = timed_render(load_scene(cmd.scene, ov), cmd.threads);
      const ImageError e = image_error(r.image, ref);
      results.back().push_back({spp, r.seconds, e});
      line.x.push_back(r.seconds);
      line.y.push_back(e.rmse);
      std::printf("%-*s %8u %10.3f %12.6g %13.6g %12.6g\n", label_width, label.c_str(), spp, r.seconds, e.rmse,
                  e.display_rmse, e.rel_mse);
      out << csv_field(label) << "," << spp << "," << r.seconds << "," << e.rmse << "," << e.display_rmse << ","
          << e.rel_mse << "\n";
    }
    lines.push_back(line);
  }
  if (!thresholds.empty()) {  // adaptive: one point per threshold
    RenderOverrides ov = adaptive;
    results.emplace_back();
    PlotSeries line{"adaptive", {}, {}};
    for (float threshold : thresholds) {
      ov.noise_threshold = threshold;
      const Scene scene = load_scene(cmd.scene, ov);
      const TimedRender r = timed_render(scene, cmd.threads);
      const ImageError e = image_error(r.image, ref);
      results.back().push_back({*ov.spp, r.seconds, e});
      line.x.push_back(r.seconds);
      line.y.push_back(e.rmse);
      std::printf("%-*s %8s %10.3f %12.6g %13.6g %12.6g  (threshold %g)\n", label_width, "adaptive", "", r.seconds,
                  e.rmse, e.display_rmse, e.rel_mse, static_cast<double>(threshold));
      out << "adaptive " << threshold << "," << *ov.spp << "," << r.seconds << "," << e.rmse << "," << e.display_rmse
          << "," << e.rel_mse << "\n";
    }
    lines.push_back(line);
  }
  OutputBatch outputs;
  outputs.add(csv, out.str());
  add_loglog_plot(outputs, plot, {"RMSE against render time: " + stem, "seconds", "RMSE"}, lines);
  outputs.commit();
  if (!samplers.empty() || !configs.empty()) {
    for (size_t i = 1; i < results.size(); ++i) compare_with_baseline(series_setups, results, i);
  } else if (!thresholds.empty()) {
    const Point& uniform = results[0].back();
    for (const auto& m : kMetrics) {
      bool extrapolated = false;
      const double target = uniform.error.*m.metric;
      const double t = seconds_to_reach(results[1], m.metric, m.power, target, extrapolated);
      std::printf(
          "adaptive (at most %u spp) reaches the uniform render's %s at %u spp (%.6g, %.3f s) in %.3f s%s: "
          "time to equal %s %.3fx\n",
          results[1].back().spp, m.name, uniform.spp, target, uniform.seconds, t, extrapolated ? " (extrapolated)" : "",
          m.name, t / uniform.seconds);
    }
  } else if (results.size() == 2) {
    const Point& plain = results[1].back();
    for (const auto& m : kMetrics) {
      bool extrapolated = false;
      const double target = plain.error.*m.metric;
      const double t = seconds_to_reach(results[0], m.metric, m.power, target, extrapolated);
      std::printf("NEE+MIS reaches the plain estimator's %s at %u spp (%.6g, %.3f s) in %.3f s%s: %.1fx less time\n",
                  m.name, plain.spp, target, plain.seconds, t, extrapolated ? " (extrapolated)" : "",
                  plain.seconds / t);
    }
  }
  std::printf("wrote %s and %s\n", std::filesystem::absolute(csv).string().c_str(),
              std::filesystem::absolute(plot).string().c_str());
  return 0;
}

const RegisterCommand kBenchConvergeCommand(
    {"bench", "converge", "RMSE and relMSE against time as spp grows; CSV and a log-log plot", [](CLI::App& app) {
       auto cmd = std::make_shared<BenchConvergeCommand>();
       app.add_option("scene", cmd->scene, "scene file (JSON)")->required();
       app.add_option("--spp", cmd->spp, "comma-separated sample counts (default 1,4,16,64,256)");
       app.add_option("--nee", cmd->nee,
                      "scene (default), on, off, or both: NEE+MIS and the plain estimator side by side");
       app.add_option("--samplers", cmd->samplers,
                      "comma-separated samplers side by side (e.g. stochastic,stratified,sobol); ratios against the "
                      "first");
       app.add_option("--configs", cmd->configs,
                      "configurations side by side, separated by ';', each comma-separated KEY=VALUE render "
                      "options (e.g. \"rr_depth=3;rr_depth=65\"); ratios against the first");
       app.add_option("--thresholds", cmd->thresholds,
                      "comma-separated noise thresholds: an adaptive series (at most --adaptive-spp) against "
                      "the uniform one");
       app.add_option("--adaptive-spp", cmd->adaptive_spp,
                      "the adaptive series' most spp (default 4 x the largest --spp)")
           ->check(count_in(2, UINT32_MAX));
       app.add_option("--min-spp", cmd->min_spp, "the adaptive series' min_spp (default the scene's)")
           ->check(count_in(2, UINT32_MAX));
       app.add_option("--ref", cmd->ref, "reference image (EXR); default: render one at --ref-spp");
       app.add_option("--ref-spp", cmd->ref_spp, "reference samples per pixel (default 8 x the largest --spp)")
           ->check(count_in(1, UINT32_MAX));
       app.add_option("--csv", cmd->csv, "table output (default SCENE-converge.csv)");
       app.add_option("--plot", cmd->plot, "log-log plot of RMSE against seconds (default SCENE-converge.png)");
       add_bench_size_options(app, cmd->width, cmd->height, cmd->threads);
       return [cmd] { return run_bench_converge(*cmd); };
     }});

}  // namespace tracer
