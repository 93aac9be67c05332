// `tracer bench trade SCENE`: for each knob of the path integrator (NEE, sampler, Fresnel
// model, Russian roulette depth, max_depth, sky sampling under an environment light, mirror images where the scene has
// a flat mirror, triangle test), the time and the error of a render at a fixed sample budget, and the error of a render
// given the baseline's time (its spp scaled by the measured speed). Error is against one reference made with the
// scene's own settings, so a knob that changes the expected image (max_depth, Fresnel) shows its bias too.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bench/bench_common.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "io/input_error.h"
#include "kernel/shading/mirror_images.h"
#include "scene/scene_loader.h"

namespace tracer {

struct BenchTradeCommand {
  std::string scene, ref;
  uint32_t spp = 64, ref_spp = 0, width = 0, height = 0;
  int threads = 0;
};
namespace {

constexpr int kRepeats = 3;  // each timing is the median of three renders

struct Knob {
  const char* name;
  std::string setting;
  RenderOverrides overrides;
  bool square_spp;  // the stratified sampler needs n x n samples
};

uint32_t nearest_square(double spp) {
  const uint32_t n = std::max<uint32_t>(1, static_cast<uint32_t>(std::lround(std::sqrt(spp))));
  return n * n;
}

std::vector<Knob> knobs(bool environment_light, bool flat_mirrors) {
  std::vector<Knob> k;
  const auto with = [](auto set) {
    RenderOverrides o;
    set(o);
    return o;
  };
  k.push_back({"baseline", "scene settings", {}, false});
  k.push_back({"nee", "on", with([](RenderOverrides& o) { o.nee = Switch::On; }), false});
  k.push_back({"nee", "off", with([](RenderOverrides& o) { o.nee = Switch::Off; }), false});
  if (environment_light) {
    k.push_back({"sky_sampling", "on", with([](RenderOverrides& o) { o.sky_sampling = Switch::On; }), false});
    k.push_back({"sky_sampling", "off", with([](RenderOverrides& o) { o.sky_sampling = Switch::Off; }), false});
  }
  k.push_back(
      {"light_sampling", "area", with([](RenderOverrides& o) { o.light_sampling = LightSampling::Area; }), false});
  k.push_back({"light_sampling", "solid-angle",
               with([](RenderOverrides& o) { o.light_sampling = LightSampling::SolidAngle; }), false});
  if (flat_mirrors) {
    k.push_back({"mirror_images", "on", with([](RenderOverrides& o) { o.mirror_images = Switch::On; }), false});
    k.push_back({"mirror_images", "off", with([](RenderOverrides& o) { o.mirror_images = Switch::Off; }), false});
  }
  k.push_back({"sampler", "stochastic", with([](RenderOverrides& o) { o.sampler = SamplerKind::Stochastic; }), false});
  k.push_back({"sampler", "stratified", with([](RenderOverrides& o) { o.sampler = SamplerKind::Stratified; }), true});
  k.push_back({"sampler", "sobol", with([](RenderOverrides& o) { o.sampler = SamplerKind::Sobol; }), false});
  k.push_back({"fresnel", "schlick", with([](RenderOverrides& o) { o.fresnel = FresnelKind::Schlick; }), false});
  k.push_back({"fresnel", "exact", with([](RenderOverrides& o) { o.fresnel = FresnelKind::Exact; }), false});
  k.push_back(
      {"triangle", "watertight", with([](RenderOverrides& o) { o.triangle_test = TriangleTest::Watertight; }), false});
  k.push_back({"triangle", "moller-trumbore",
               with([](RenderOverrides& o) { o.triangle_test = TriangleTest::MollerTrumbore; }), false});
  for (uint32_t d : {1u, 3u, 8u, 65u})
    k.push_back(
        {"rr_depth", d == 65u ? "off" : std::to_string(d), with([d](RenderOverrides& o) { o.rr_depth = d; }), false});
  for (uint32_t d : {1u, 2u, 4u, 8u, 16u})
    k.push_back({"max_depth", std::to_string(d), with([d](RenderOverrides& o) { o.max_depth = d; }), false});
  return k;
}

// Applies a knob's overrides on top of the common ones.
RenderOverrides combine(RenderOverrides base, const RenderOverrides& knob) {
  base.override_with(knob);
  if (knob.fresnel) base.fresnel = knob.fresnel;
  return base;
}

// The stratified sampler, the knob's or the scene's own, needs n x n samples.
bool square_spp(const Scene& probe, const Knob& knob) {
  return knob.square_spp || (!knob.overrides.sampler && probe.settings.sampler == SamplerKind::Stratified);
}

// A knob's overrides at the budget's spp.
RenderOverrides knob_overrides(const BenchTradeCommand& cmd, const RenderOverrides& base, const Scene& probe,
                               const Knob& knob) {
  RenderOverrides ov = combine(base, knob.overrides);
  ov.spp = square_spp(probe, knob) ? nearest_square(cmd.spp) : cmd.spp;
  return ov;
}

// Loads the scene under a knob's overrides: InputError naming the knob when it cannot take them.
void check_knob(const BenchTradeCommand& cmd, const RenderOverrides& base, const Scene& probe, const Knob& knob) {
  try {
    load_scene(cmd.scene, knob_overrides(cmd, base, probe, knob));
  } catch (const InputError& e) {
    throw InputError("bench trade: knob " + std::string(knob.name) + " " + knob.setting + ": " + e.what());
  }
}

}  // namespace

static int run_bench_trade(const BenchTradeCommand& cmd) {
  if (cmd.spp == 0) throw InputError("--spp: must be at least 1");
  RenderOverrides base;
  if (cmd.width) base.width = cmd.width;
  if (cmd.height) base.height = cmd.height;
  const Scene probe = load_scene(cmd.scene, base);
  if (probe.settings.integrator != IntegratorKind::Path)
    throw InputError(cmd.scene +
                     ": bench trade measures the path integrator's knobs; give a scene with \"integrator\": \"path\"");
  if (probe.settings.sampler == SamplerKind::Center || probe.settings.sampler == SamplerKind::Grid)
    base.sampler = SamplerKind::Stochastic;
  const SceneView probe_view = probe.view();
  const bool flat_mirrors = std::any_of(probe.primitives.begin(), probe.primitives.end(),
                                        [&](const Primitive& p) { return is_planar_mirror(probe_view, p); });
  const std::vector<Knob> all = knobs(samples_environment(probe.background.kind), flat_mirrors);
  // Every knob's render is one the scene can make, checked before the reference renders (a
  // knob refused after 36 renders wasted them).
  for (const Knob& knob : all) check_knob(cmd, base, probe, knob);
  std::printf("tracer bench trade %s: %ux%u, %u spp budget; seconds are the median of %d renders\n", cmd.scene.c_str(),
              probe.settings.width, probe.settings.height, cmd.spp, kRepeats);
  const Image ref = reference_image(cmd.scene, base, cmd.ref, cmd.ref_spp ? cmd.ref_spp : 16ull * cmd.spp, cmd.threads,
                                    std::filesystem::path(cmd.scene).stem().string() + "-trade-ref.exr");

  std::printf("%-12s %-15s | %6s %9s %11s %11s | %14s %9s %11s\n", "knob", "setting", "spp", "seconds", "RMSE",
              "relMSE", "equal-time spp", "seconds", "RMSE");
  double baseline_seconds = 0;
  for (const Knob& knob : all) {
    RenderOverrides ov = knob_overrides(cmd, base, probe, knob);
    const bool square = square_spp(probe, knob);
    const TimedRender fixed = timed_render(load_scene(cmd.scene, ov), cmd.threads, kRepeats);
    const ImageError fixed_error = image_error(fixed.image, ref);
    if (baseline_seconds == 0) baseline_seconds = fixed.seconds;
    const double scaled = static_cast<double>(*ov.spp) * baseline_seconds / fixed.seconds;
    ov.spp = square ? nearest_square(scaled) : std::max<uint32_t>(1, static_cast<uint32_t>(std::lround(scaled)));
    const TimedRender equal = timed_render(load_scene(cmd.scene, ov), cmd.threads, kRepeats);
    const ImageError equal_error = image_error(equal.image, ref);
    std::printf("%-12s %-15s | %6u %9.3f %11.5g %11.5g | %14u %9.3f %11.5g\n", knob.name, knob.setting.c_str(),
                square ? nearest_square(cmd.spp) : cmd.spp, fixed.seconds, fixed_error.rmse, fixed_error.rel_mse,
                *ov.spp, equal.seconds, equal_error.rmse);
  }
  return 0;
}

const RegisterCommand kBenchTradeCommand(
    {"bench", "trade", "time and error of each knob, at a fixed sample budget and at equal time", [](CLI::App& app) {
       auto cmd = std::make_shared<BenchTradeCommand>();
       app.add_option("scene", cmd->scene, "scene file (JSON)")->required();
       app.add_option("--spp", cmd->spp, "the fixed sample budget (default 64)")->check(count_in(1, UINT32_MAX));
       app.add_option("--ref", cmd->ref, "reference image (EXR); default: render one at --ref-spp");
       app.add_option("--ref-spp", cmd->ref_spp, "reference samples per pixel (default 16 x --spp)")
           ->check(count_in(1, UINT32_MAX));
       add_bench_size_options(app, cmd->width, cmd->height, cmd->threads);
       return [cmd] { return run_bench_trade(*cmd); };
     }});

}  // namespace tracer
