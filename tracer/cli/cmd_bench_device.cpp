// `tracer bench device`: frames per second and Mrays/s of the Whitted renderer on the CPU
// or the GPU, as the tables of the CUDA Whitted reference design (effects and resolution),
// with the CPU measured in the same run as the baseline for the GPU's speed-up.
#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/command_registry.h"
#include "cli/commands.h"
#include "io/input_error.h"
#include "options/effects.h"
#include "render/render_cpu.h"
#include "render/render_cuda.h"
#include "scene/scene_loader.h"

namespace tracer {

struct BenchDeviceCommand {
  std::string device = "cuda", scenes = "scenes";
  int frames = 5;
  int threads = 0;
};
namespace {

struct FrameTiming {
  double seconds = 0;  // median seconds per frame: the kernel's on the GPU, render_cpu's on the CPU
  uint64_t rays = 0;   // per frame
  double fps() const { return seconds > 0 ? 1.0 / seconds : 0.0; }
  double mrays() const { return seconds > 0 ? static_cast<double>(rays) / seconds / 1e6 : 0.0; }
};

FrameTiming time_frames(const Scene& scene, bool cuda, int frames, int threads) {
  std::vector<double> times;
  FrameTiming timing;
  for (int f = 0; f < frames; ++f) {
    RenderStats stats;
    if (cuda) {
      CudaRunInfo info;
      render_cuda(scene, stats, info);
      times.push_back(info.kernel_seconds);
    } else {
      const auto start = std::chrono::steady_clock::now();
      render_cpu(scene, threads, stats);
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    timing.rays = stats.rays.camera + stats.rays.secondary + stats.rays.shadow;
  }
  std::sort(times.begin(), times.end());
  timing.seconds = times[times.size() / 2];
  return timing;
}

struct SamplerSetup {
  const char* label;
  SamplerKind sampler;
  uint32_t spp;
};
constexpr SamplerSetup kSamplers[] = {{"1 spp center", SamplerKind::Center, 1},
                                      {"2 spp stochastic", SamplerKind::Stochastic, 2},
                                      {"4 spp grid", SamplerKind::Grid, 4}};

Scene load_at(const std::string& path, uint32_t width, uint32_t height, const SamplerSetup& s, Effects effects) {
  RenderOverrides ov;
  ov.width = width;
  ov.height = height;
  ov.sampler = s.sampler;
  ov.spp = s.spp;
  ov.effects = effects;
  ov.integrator = IntegratorKind::Whitted;
  return load_scene(path, ov);
}

uint64_t triangle_count(const Scene& scene) {
  return std::count_if(scene.primitives.begin(), scene.primitives.end(),
                       [](const Primitive& p) { return p.kind == ShapeKind::Triangle; });
}

// The scene under `dir` with the most triangles (ties: the first path in sorted order).
std::string largest_mesh_scene(const std::string& dir, uint64_t& triangles) {
  std::vector<std::string> paths;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  std::string best;
  triangles = 0;
  for (const std::string& p : paths) {
    uint64_t n = 0;
    try {
      n = triangle_count(load_scene(p));
    } catch (const InputError& e) {  // scenes/large/ before ci/generate-meshes.sh ran
      if (std::string(e.what()).find("no such file") == std::string::npos) throw;
      std::printf("(skipping %s: %s)\n", p.c_str(), e.what());
      continue;
    }
    if (n > triangles) best = p, triangles = n;
  }
  if (best.empty()) throw InputError(dir + ": no scene with a triangle mesh");
  return best;
}

}  // namespace

static int run_bench_device(const BenchDeviceCommand& cmd) {
  if (cmd.device != "cpu" && cmd.device != "cuda")
    throw InputError("--device " + cmd.device + ": expected cpu or cuda");
  if (cmd.frames < 1) throw InputError("--frames: must be at least 1");
  const bool cuda = cmd.device == "cuda";
  const std::string cornell = (std::filesystem::path(cmd.scenes) / "cornell-box.json").string();
  const int threads = cmd.threads > 0 ? cmd.threads : omp_get_max_threads();
  const std::string cpu_name = "CPU (" + std::to_string(threads) + " threads)";
  const std::string device_name = cuda ? cuda_device_description() : cpu_name;
  std::printf("tracer bench device: %s; median of %d frames; seconds are %s\n\n", device_name.c_str(), cmd.frames,
              cuda ? "kernel time (CUDA events), the CPU baseline render_cpu's wall time" : "render_cpu's wall time");

  uint64_t triangles = 0;
  const std::string mesh = largest_mesh_scene(cmd.scenes, triangles);
  std::printf("Whitted, all effects, 720x480%s\n", cuda ? "; speed-up against the CPU in this run" : "");
  std::printf("%-44s %-18s %12s %10s %10s %10s%s\n", "scene", "samples", "s/frame", "frames/s", "Mrays/s",
              "Mrays/frame", cuda ? "   CPU s/frame  speed-up" : "");
  for (const std::string& path : {cornell, mesh}) {
    for (const SamplerSetup& s : {kSamplers[0], kSamplers[2]}) {
      const Scene scene = load_at(path, 720, 480, s, kEffectAll);
      const FrameTiming t = time_frames(scene, cuda, cmd.frames, threads);
      const std::string name = path == mesh ? path + " (" + std::to_string(triangles) + " tri)" : path;
      std::printf("%-44s %-18s %12.6f %10.1f %10.1f %10.3f", name.c_str(), s.label, t.seconds, t.fps(), t.mrays(),
                  static_cast<double>(t.rays) / 1e6);
      if (cuda) {
        const FrameTiming base = time_frames(scene, false, cmd.frames, threads);
        std::printf("   %11.6f  %8.1fx", base.seconds, base.seconds / t.seconds);
      }
      std::printf("\n");
    }
  }

  std::printf("\nFrames/s per effect, Cornell box 720x480 (the reference design: 20 frames/s, all effects, GTX 970)\n");
  std::printf("%-32s", "effects");
  for (const SamplerSetup& s : kSamplers) std::printf(" %18s", s.label);
  std::printf("\n");
  for (const Effects effects : {kEffectNone, kEffectShadows, kEffectReflection, kEffectRefraction, kEffectAll}) {
    std::printf("%-32s", effects_name(effects).c_str());
    for (const SamplerSetup& s : kSamplers)
      std::printf(" %18.1f", time_frames(load_at(cornell, 720, 480, s, effects), cuda, cmd.frames, threads).fps());
    std::printf("\n");
  }

  std::printf("\nFrames/s against resolution, Cornell box, all effects\n");
  std::printf("%-12s", "resolution");
  for (const SamplerSetup& s : kSamplers) std::printf(" %18s", s.label);
  std::printf("\n");
  const uint32_t sizes[][2] = {{640, 480}, {720, 480}, {1280, 720}, {1920, 1080}};
  for (const auto& size : sizes) {
    std::printf("%-12s", (std::to_string(size[0]) + "x" + std::to_string(size[1])).c_str());
    for (const SamplerSetup& s : kSamplers)
      std::printf(" %18.1f",
                  time_frames(load_at(cornell, size[0], size[1], s, kEffectAll), cuda, cmd.frames, threads).fps());
    std::printf("\n");
  }
  return 0;
}

const RegisterCommand kBenchDeviceCommand(
    {"bench", "device", "Whitted frames/s and Mrays/s on a device: per effect, per resolution", [](CLI::App& app) {
       auto cmd = std::make_shared<BenchDeviceCommand>();
       app.add_option("--device", cmd->device, "cuda (default; the CPU is timed too, as the baseline) or cpu");
       app.add_option("--frames", cmd->frames, "frames per measurement; the median is reported (default 5)")
           ->check(count_in(1, 1000));
       app.add_option("--scenes", cmd->scenes,
                      "scene directory: cornell-box.json and the mesh scenes (default scenes)");
       add_threads_option(app, cmd->threads);
       return [cmd] { return run_bench_device(*cmd); };
     }});

}  // namespace tracer
