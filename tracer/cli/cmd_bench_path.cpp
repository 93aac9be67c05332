// `tracer bench path [SCENE ...]`: what the path tracer costs beyond traversal. For each
// scene and thread count: the render's Mrays/s (sampling, shading, film and traversal),
// per thread; the rays it cast, recorded once and replayed through closest-hit and any-hit
// alone on as many threads; their ratio (1 would mean everything but traversal is free);
// and the render time with the generic kernel against the kernel specialised to the
// scene's features (tracer/render/cpu_kernel.h). Medians of --repeats runs.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

#include "bench/bench_common.h"
#include "bench/ray_recorder.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "cli/number_checks.h"
#include "io/input_error.h"
#include "kernel/accel/trace.h"
#include "options/enum_names.h"
#include "render/cpu_kernel.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"

namespace tracer {

struct BenchPathCommand {
  std::vector<std::string> scenes;
  uint32_t spp = 4, size = 128, repeats = 3;
  std::string threads = "1,2", sampler;  // sampler: empty keeps each scene's own
};
namespace {

struct Replay {
  std::vector<Ray> rays;
  std::vector<float> tmax;
};

Replay unpack(const std::vector<float>& packed) {
  Replay r;
  for (size_t i = 0; i + 7 <= packed.size(); i += 7) {
    r.rays.push_back({{packed[i], packed[i + 1], packed[i + 2]}, {packed[i + 3], packed[i + 4], packed[i + 5]}});
    r.tmax.push_back(packed[i + 6]);
  }
  return r;
}

// Closest-hit over one set and any-hit over the other, in chunks of 1024 on `threads`, into
// answers allocated (and touched) before the clock starts.
void replay(const SceneView& view, const CpuKernelVariant& kernel, const Replay& closest, const Replay& any,
            int threads, std::vector<Hit>& hits, std::vector<uint8_t>& occluded) {
  constexpr size_t kChunk = 1024;
  const int64_t closest_chunks = static_cast<int64_t>((closest.rays.size() + kChunk - 1) / kChunk);
  const int64_t any_chunks = static_cast<int64_t>((any.rays.size() + kChunk - 1) / kChunk);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int64_t c = 0; c < closest_chunks + any_chunks; ++c) {
    const bool is_any = c >= closest_chunks;
    const size_t begin = static_cast<size_t>(is_any ? c - closest_chunks : c) * kChunk;
    const Replay& set = is_any ? any : closest;
    const size_t n = std::min(kChunk, set.rays.size() - begin);
    if (is_any)
      kernel.trace_any(view, &set.rays[begin], &set.tmax[begin], n, &occluded[begin]);
    else
      kernel.trace_closest(view, &set.rays[begin], &set.tmax[begin], n, &hits[begin]);
  }
}

}  // namespace

static int run_bench_path(const BenchPathCommand& cmd) {
  std::vector<std::string> scenes = cmd.scenes;
  if (scenes.empty()) {
    scenes.push_back("scenes/cornell-box-path.json");
    if (std::filesystem::exists("scenes/generated/bunny.obj")) scenes.push_back("scenes/large/bunny.json");
  }
  std::vector<int> thread_counts;
  for (const uint32_t t : parse_spp_list("--threads", cmd.threads)) {
    if (t == 0 || t > 1024) throw InputError("--threads " + cmd.threads + ": thread counts are 1 to 1024");
    thread_counts.push_back(static_cast<int>(t));
  }
  std::optional<SamplerKind> sampler;
  if (!cmd.sampler.empty()) sampler = parse_enum<SamplerKind>(cmd.sampler, "--sampler");
  std::printf("tracer bench path: %ux%u pixels, %u spp, %s, median of %u runs; Mrays/s\n", cmd.size, cmd.size, cmd.spp,
              sampler ? ("sampler " + cmd.sampler + " in every scene").c_str() : "each scene's sampler", cmd.repeats);
  std::printf("%-28s %7s %-16s %10s %10s %10s %8s | %10s %10s %8s\n", "scene", "threads", "kernel", "path",
              "per thread", "replayed", "ratio", "generic s", "special s", "speed-up");
  for (const std::string& path : scenes) {
    RenderOverrides ov;
    ov.width = ov.height = cmd.size;
    ov.spp = cmd.spp;
    ov.sampler = sampler;
    const Scene scene = load_scene(path, ov);
    const SceneView view = scene.view();
    const CpuKernelVariant& special = cpu_kernel_for(view.features);
    const CpuKernelVariant& generic = cpu_kernel_for(view.features, true);
    const RecordedRays recorded = record_rays(view, 0, cmd.spp);
    const Replay closest = unpack(recorded.closest), any = unpack(recorded.any);
    const uint64_t replayed = closest.rays.size() + any.rays.size();
    for (const int threads : thread_counts) {
      RenderStats stats;
      const auto render_with = [&](const CpuKernelVariant& kernel) {
        return median_seconds(cmd.repeats, [&] { render_cpu_film(scene, {0, cmd.spp}, threads, stats, {}, &kernel); });
      };
      const double special_s = render_with(special), generic_s = render_with(generic);
      const uint64_t rays = stats.rays.camera + stats.rays.secondary + stats.rays.shadow;
      if (rays != replayed)
        throw std::runtime_error(path + ": the render cast " + std::to_string(rays) + " rays but " +
                                 std::to_string(replayed) + " were recorded");
      std::vector<Hit> hits(closest.rays.size());
      std::vector<uint8_t> occluded(any.rays.size());
      const double replay_s =
          median_seconds(cmd.repeats, [&] { replay(view, special, closest, any, threads, hits, occluded); });
      const double path_rate = static_cast<double>(rays) / special_s / 1e6;
      const double replay_rate = static_cast<double>(rays) / replay_s / 1e6;
      const std::string label = std::filesystem::path(path).filename().string() + " (" +
                                enum_name(scene.settings.sampler) + ")";  // the sampler it ran with
      std::printf("%-28s %7d %-16s %10.2f %10.2f %10.2f %8.2f | %10.3f %10.3f %8.2f\n", label.c_str(), threads,
                  cpu_kernel_name(special).c_str(), path_rate, path_rate / threads, replay_rate,
                  path_rate / replay_rate, generic_s, special_s, generic_s / special_s);
    }
  }
  std::printf("ratio: path Mrays/s over the replayed rate of the same rays (traversal alone)\n");
  return 0;
}

const RegisterCommand kBenchPathCommand(
    {"bench", "path", "path tracer Mrays/s against the same rays' traversal-only rate; generic vs specialised kernel",
     [](CLI::App& app) {
       auto cmd = std::make_shared<BenchPathCommand>();
       app.add_option(
           "scenes", cmd->scenes,
           "scene files (default scenes/cornell-box-path.json and, when generated, scenes/large/bunny.json)");
       app.add_option("--spp", cmd->spp, "samples per pixel (default 4)")->check(count_in(1, 4096));
       app.add_option("--size", cmd->size, "image width and height (default 128)")->check(count_in(1, 4096));
       app.add_option("--repeats", cmd->repeats, "runs per measurement; the median is kept (default 3)")
           ->check(count_in(1, 100));
       app.add_option("--threads", cmd->threads, "comma-separated thread counts (default 1,2)");
       app.add_option("--sampler", cmd->sampler,
                      "render every scene with this sampler (center, grid, stochastic, stratified, sobol) instead of "
                      "its own");
       return [cmd] { return run_bench_path(*cmd); };
     }});

}  // namespace tracer
