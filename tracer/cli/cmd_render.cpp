#include <OpenImageIO/hash.h>
#include <OpenImageIO/imageio.h>
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "accel/acceleration.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "image/image_io.h"
#include "io/input_error.h"
#include "io/out_of_memory.h"
#include "io/output_batch.h"
#include "io/output_paths.h"
#include "io/text_file.h"
#include "options/number_text.h"
#include "options/render_options.h"
#include "render/partial_file.h"
#include "render/progress.h"
#include "render/render_adaptive.h"
#include "render/render_cpu.h"
#include "render/render_cuda.h"
#include "scene/gltf_file.h"
#include "scene/scene_loader.h"

namespace tracer {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Fail before rendering when the output could not be written anyway. A sample range
// writes a partial file, anything else an image.
void check_output_path(const std::string& path, bool partial) {
  const std::filesystem::path p(path);
  if (partial) {
    check_output_location(path, "-o");
    if (p.extension() != ".partial") throw InputError(path + ": --samples writes a partial file; name it NAME.partial");
    return;
  }
  if (p.extension() == ".partial")
    throw InputError(path + ": a .partial file holds a sample range; give --samples A:B");
  check_image_output(path, "-o");
}

// The output and the stats file may name no file the render reads, nor each other.
void refuse_overwriting_inputs(const Scene& scene, const std::string& output, const RenderCommand& cmd) {
  refuse_outputs_naming_inputs({{output, "-o"}, {cmd.stats, "--stats"}, {cmd.sample_map, "--sample-map"}},
                               scene.files_read());
}

// What makes two partial files parts of one render: every option its identity records.
Json render_identity(const Scene& scene) {
  return Json::parse(recorded_options(scene.settings, scene.background.kind).to_json().dump());
}

}  // namespace

void add_scene_options(CLI::App& app, RenderCommand& cmd) {
  app.add_option("scene", cmd.scene, "scene file (JSON), or a glTF 2.0 file (.gltf, .glb)")->required();
  for (const OptionInfo& o : option_table()) app.add_option(option_flag(o.name), cmd.options[o.name], o.help);
  app.add_option("--camera", cmd.camera, "glTF files: the camera, by index or name (default: the first)");
  app.add_option("--background", cmd.background,
                 "glTF files: a constant background R,G,B (default: 1,1,1, the neutral sky of a viewer)");
  app.add_option("--environment", cmd.environment,
                 "an equirectangular image (.hdr, .exr, ...) as the background of any scene, lighting it "
                 "(docs/scene-format.md, \"environment\")");
  app.add_option("--samples", cmd.samples,
                 "A:B renders only samples [A, B) of every pixel (render: into NAME.partial, for tracer merge)");
}

// "R,G,B": three decimals in [0, 1e6], the radiance of a constant background.
static Vec3 parse_colour_text(const std::string& text, const std::string& context) {
  float c[3];
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = i < 2 ? text.find(',', start) : text.size();
    const auto v = comma == std::string::npos
                       ? std::nullopt
                       : parse_decimal(std::string_view(text).substr(start, comma - start), 0.0, 1e6);
    if (!v || (i == 2 && comma != text.size()))
      throw InputError(context + ": expected R,G,B, three decimals from 0 to 1e6, got \"" + text + "\"");
    c[i] = static_cast<float>(*v);
    start = comma + 1;
  }
  return {c[0], c[1], c[2]};
}

RenderOverrides scene_overrides(const RenderCommand& cmd) {
  RenderOverrides overrides;
  for (const auto& [name, text] : cmd.options)
    if (text) parse_option_text(name, *text, cmd.scene + ": command line ", overrides);
  overrides.camera = cmd.camera;
  if (cmd.background)
    overrides.background = parse_colour_text(*cmd.background, cmd.scene + ": command line --background");
  if (cmd.background && cmd.environment)
    throw InputError(cmd.scene + ": command line --background and --environment: both set the background; give one");
  overrides.environment = cmd.environment;
  return overrides;
}

static int run_render(const RenderCommand& cmd) {
  if (cmd.device != "cpu" && cmd.device != "cuda")
    throw InputError("--device " + cmd.device + ": expected cpu or cuda");
  const std::string output =
      cmd.output.empty() ? std::filesystem::path(cmd.scene).stem().string() + ".png" : cmd.output;
  const bool partial = !cmd.samples.empty();
  check_output_path(output, partial);
  if (!cmd.stats.empty()) check_output_location(cmd.stats, "--stats");

  if (cmd.device == "cuda") cuda_device_description();  // fail before loading when there is no GPU
  const auto t_load = Clock::now();
  const RenderOverrides overrides = scene_overrides(cmd);
  const std::string scene_text =
      read_text_file(cmd.scene, "scene file", is_gltf_path(cmd.scene) ? kMaxGltfFileBytes : UINT64_MAX);
  const Scene scene = load_scene_text(scene_text, cmd.scene, overrides);  // loading includes the BVH build
  const double load_build_s = seconds_since(t_load);
  refuse_overwriting_inputs(scene, output, cmd);
  const double build_s = scene.report.build_seconds;

  const RenderSettings& rs = scene.settings;
  const bool adaptive = adaptive_render(rs);
  if (adaptive && partial)
    throw InputError(cmd.scene +
                     ": --samples: an adaptive render (noise_threshold, target_error) decides its samples "
                     "from all of them, so it cannot be split into sample ranges; render it whole");
  if (!cmd.sample_map.empty() && !adaptive)
    throw InputError(cmd.scene + ": --sample-map: only an adaptive render (noise_threshold, target_error) has one");
  if (!cmd.sample_map.empty()) check_image_output(cmd.sample_map, "--sample-map");
  // A float image holds whole numbers exactly up to 2^24: 16,777,217 samples would read 16,777,216.
  if (!cmd.sample_map.empty() && is_float_format(cmd.sample_map) && rs.spp > (1u << 24))
    throw InputError(cmd.scene + ": --sample-map " + cmd.sample_map + ": a pixel may take up to " +
                     std::to_string(rs.spp) +
                     " samples, and a float image holds counts exactly only up to 2^24 (16777216): lower spp "
                     "or write the map as PNG (each count as its fraction of spp)");
  const SampleRange range = partial ? parse_sample_range(cmd.samples, rs.spp) : SampleRange{0, rs.spp};
  AdaptiveFilm adaptive_film;
  RenderStats stats;
  CudaRunInfo cuda;
  Partial part;
  const auto t_render = Clock::now();
  const std::string film_size = std::to_string(rs.width) + "x" + std::to_string(rs.height);
  naming_file_when_out_of_memory(cmd.scene, "allocating its " + film_size + " film", [&] {
    if (cmd.device == "cuda" && adaptive) {
      adaptive_film = render_cuda_adaptive(scene, stats, cuda);
    } else if (cmd.device == "cuda") {
      part.film = render_cuda_film(scene, range, stats, cuda);  // one launch: no progress to draw
    } else if (adaptive) {
      ProgressBar bar(!cmd.quiet);
      adaptive_film = render_cpu_adaptive(scene, cmd.threads, stats,
                                          [&](uint64_t done, uint64_t total) { bar.update(done, total); });
      bar.finish();
    } else {
      ProgressBar bar(!cmd.quiet);  // tiles, or under --schedule stream samples: each callback says
      part.film = render_cpu_film(scene, range, cmd.threads, stats,
                                  [&](uint64_t done, uint64_t total) { bar.update(done, total); });
      bar.finish();
    }
  });
  const double render_s = seconds_since(t_render);
  // The image (or partial file) and the --stats file land together or not at all.
  OutputBatch outputs;
  if (partial) {
    part.header = {render_identity(scene),
                   cmd.scene,
                   OIIO::SHA1::digest(scene_text.data(), scene_text.size()),
                   rs.spp,
                   stats.nonfinite_samples,
                   stats.overflow_samples};
    outputs.add(output, encode_partial(part));
  } else if (adaptive) {
    add_image(outputs, resolve_adaptive(adaptive_film), output);
    if (!cmd.sample_map.empty()) {
      Image map = adaptive_sample_map(adaptive_film);
      // An 8-bit image holds [0, 1]: there each count is its fraction of spp (spp is white).
      if (!is_float_format(cmd.sample_map))
        for (float& v : map.rgb) v /= static_cast<float>(rs.spp);
      add_image(outputs, map, cmd.sample_map);
    }
  } else {
    add_image(outputs, resolve_film(part.film, rs.spp), output);
  }
  uint64_t samples_taken = static_cast<uint64_t>(rs.width) * rs.height * (range.end - range.begin);
  if (adaptive) {
    samples_taken = 0;
    for (const uint32_t n : adaptive_film.samples) samples_taken += n;
  }
  const double mean_spp = static_cast<double>(samples_taken) / (static_cast<double>(rs.width) * rs.height);

  const uint64_t rays = stats.rays.camera + stats.rays.secondary + stats.rays.shadow;
  const double mrays = render_s > 0.0 ? static_cast<double>(rays) / render_s / 1e6 : 0.0;
  if (!cmd.stats.empty()) {
    nlohmann::ordered_json j;
    j["scene"] = cmd.scene;
    j["output"] = output;
    j["width"] = rs.width;
    j["height"] = rs.height;
    j["spp"] = rs.spp;
    j["samples"] = {range.begin, range.end};
    j["device"] = cmd.device == "cuda" ? cuda.device : "cpu";
    if (cmd.device == "cuda") {
      j["device_bytes"] = cuda.device_bytes;
      j["cuda_seconds"] = {
          {"upload", cuda.upload_seconds}, {"kernel", cuda.kernel_seconds}, {"download", cuda.download_seconds}};
    } else {
      j["threads"] = cmd.threads > 0 ? cmd.threads : omp_get_max_threads();
      j["cpu_kernel"] = stats.cpu_kernel;
    }
    j["seconds"] = {{"load", load_build_s - build_s}, {"build", build_s}, {"render", render_s}};
    j["rays"] = {{"camera", stats.rays.camera},
                 {"shadow", stats.rays.shadow},
                 {"secondary", stats.rays.secondary},
                 {"total", rays}};
    j["mrays_per_second"] = mrays;
    if (rs.schedule == Schedule::Stream)
      j["stream"] = {{"width", rs.stream_width},
                     {"order", enum_name(rs.stream_order)},
                     {"batches", stats.stream.batches},
                     {"waves", stats.stream.waves},
                     {"largest_queue", stats.stream.largest_queue},
                     {"shadow_rays", stats.stream.shadow_rays},
                     {"bytes_per_state", stats.stream.bytes_per_state},
                     {"state_bytes", stats.stream.state_bytes}};
    if (adaptive)
      j["adaptive"] = {{"noise_threshold", shortest_decimal(rs.noise_threshold)},
                       {"target_error", shortest_decimal(rs.target_error)},
                       {"image_error", adaptive_film.image_error},
                       {"checkpoints", adaptive_checkpoints(rs.min_spp, rs.spp)},
                       {"samples_taken", samples_taken},
                       {"mean_spp", mean_spp}};
    j["nonfinite_samples"] = stats.nonfinite_samples;
    j["overflow_samples"] = stats.overflow_samples;
    j["degenerate_triangles"] = scene.report.degenerate_triangles;
    const AccelSummary& accel = scene.report.accel;
    j["accel"] = {{"kind", accel.name}, {"nodes", accel.nodes}};
    if (rs.accel == AccelKind::Grid) j["accel"]["cells"] = accel.cells;
    j["features"] = feature_names(scene.features);
    j["options"] = resolved_options(rs).to_json();
    outputs.add(cmd.stats, j.dump(2) + "\n");
  }
  outputs.commit();
  if (!cmd.quiet && cmd.device == "cuda")
    std::fprintf(stderr, "%s: kernel %.6f s, upload %.3f s, download %.3f s\n", cuda.device.c_str(),
                 cuda.kernel_seconds, cuda.upload_seconds, cuda.download_seconds);
  if (!cmd.quiet && rs.noise_threshold > 0.0f)
    std::fprintf(stderr, "adaptive: noise threshold %g, %.1f spp on average (from %u to %u)\n",
                 static_cast<double>(rs.noise_threshold), mean_spp, std::min(rs.min_spp, rs.spp), rs.spp);
  if (!cmd.quiet && rs.target_error > 0.0f)
    std::fprintf(
        stderr, "target error %g: estimated relative RMS error %.4g at %.0f spp%s\n",
        static_cast<double>(rs.target_error), adaptive_film.image_error, mean_spp,
        adaptive_film.image_error < static_cast<double>(rs.target_error) ? "" : " (the most spp: not reached)");
  if (!cmd.quiet)
    std::fprintf(stderr, "%ux%u, %u spp, %.3f s, %.2fM rays, %.2f Mrays/s, %llu NaN/inf samples\n", rs.width, rs.height,
                 rs.spp, render_s, static_cast<double>(rays) / 1e6, mrays,
                 static_cast<unsigned long long>(stats.nonfinite_samples));
  if (!cmd.quiet && scene.report.degenerate_triangles > 0)
    std::fprintf(stderr, "note: %u mesh triangles of zero area were left out (they have no normal)\n",
                 scene.report.degenerate_triangles);
  if (stats.overflow_samples > 0)
    std::fprintf(stderr,
                 "warning: %llu samples were left out (film overflow): a sample of 2^30 or more, or a pixel's sum "
                 "over its samples reaching 2^30 (lower spp x radiance)\n",
                 static_cast<unsigned long long>(stats.overflow_samples));
  std::printf("wrote %s\n", std::filesystem::absolute(output).string().c_str());
  return 0;
}

const RegisterCommand kRenderCommand(
    {"", "render", "render a scene to an image", [](CLI::App& app) {
       auto cmd = std::make_shared<RenderCommand>();
       add_scene_options(app, *cmd);
       app.add_option("-o,--output", cmd->output,
                      "output image (.exr linear float, .png sRGB, ...); default SCENE.png");
       add_threads_option(app, cmd->threads);
       app.add_option("--device", cmd->device, "cpu or cuda");
       app.add_option("--stats", cmd->stats, "write timings and ray counts as JSON");
       app.add_option("--sample-map", cmd->sample_map,
                      "adaptive sampling: write each pixel's sample count as an image (.exr: the counts; "
                      ".png: count / spp, sRGB-encoded, spp white)");
       app.add_flag("--quiet", cmd->quiet, "no progress bar or summary");
       return [cmd] { return run_render(*cmd); };
     }});

}  // namespace tracer
