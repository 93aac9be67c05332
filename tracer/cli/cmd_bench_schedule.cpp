// `tracer bench schedule [SCENE ...]`: the megakernel against the stream schedule on the CPU
// (docs/path.md, "The stream schedule"). For each scene and thread count: the megakernel's
// Mrays/s, then per stream width and queue order (render.stream_order: queue, or sorted by the
// rays' keys before each wave's traces) the stream's Mrays/s and its ratio to the megakernel,
// the bytes of ray state per sample in flight and in all, the largest closest-hit queue, the
// waves and the shadow rays per wave. Medians of --repeats runs; every image must hash alike.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "bench/bench_common.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "cli/number_checks.h"
#include "image/pixel_hash.h"
#include "io/input_error.h"
#include "options/enum_names.h"
#include "render/render_cpu.h"
#include "render/stream_memory.h"
#include "scene/scene_loader.h"

namespace tracer {

struct BenchScheduleCommand {
  std::vector<std::string> scenes;
  uint32_t spp = 4, size = 128, repeats = 3;
  std::string threads = "1,2";
  std::string widths = "4096,65536,262144";
  std::string orders = "queue,sorted";
};

static int run_bench_schedule(const BenchScheduleCommand& cmd) {
  std::vector<std::string> scenes = cmd.scenes;
  if (scenes.empty()) {
    scenes.push_back("scenes/cornell-box-path.json");
    for (const char* large : {"scenes/large/bunny.json", "scenes/large/terrain.json"})
      if (std::filesystem::exists("scenes/generated/bunny.obj") && std::filesystem::exists(large))
        scenes.push_back(large);
  }
  std::vector<int> thread_counts;
  for (const uint32_t t : parse_spp_list("--threads", cmd.threads)) {
    if (t == 0 || t > 1024) throw InputError("--threads " + cmd.threads + ": thread counts are 1 to 1024");
    thread_counts.push_back(static_cast<int>(t));
  }
  const std::vector<uint32_t> widths = parse_spp_list("--widths", cmd.widths);
  for (const uint32_t w : widths)
    if (w == 0 || w > kMaxStreamWidth)
      throw InputError("--widths " + cmd.widths + ": widths are 1 to " + std::to_string(kMaxStreamWidth));
  const std::vector<StreamOrder> orders = parse_enum_list<StreamOrder>(cmd.orders, "--orders " + cmd.orders);
  if (orders.empty()) throw InputError("--orders: expected queue, sorted or both");
  // Every scene loads and every width fits in memory before the first row is measured.
  for (const std::string& path : scenes) {
    RenderOverrides ov;
    ov.width = ov.height = cmd.size;
    ov.spp = cmd.spp;
    const Scene scene = load_scene(path, ov);
    SceneView view = scene.view();
    view.settings.schedule = Schedule::Stream;
    view.settings.stream_order = StreamOrder::Sorted;  // the larger of the orders' states
    for (const uint32_t w : widths) {
      view.settings.stream_width = w;
      if (const auto why =
              stream_memory_refusal(view, static_cast<uint64_t>(cmd.size) * cmd.size * cmd.spp, "--widths"))
        throw InputError(path + ": " + *why);
    }
  }
  std::printf("tracer bench schedule: %ux%u pixels, %u spp, median of %u runs\n", cmd.size, cmd.size, cmd.spp,
              cmd.repeats);
  std::printf("%-16s %7s %-10s %8s %10s %7s %9s %9s %9s %7s %12s\n", "scene", "threads", "schedule", "width", "Mrays/s",
              "ratio", "B/state", "state MB", "queue", "waves", "shadow/wave");
  for (const std::string& path : scenes) {
    for (const int threads : thread_counts) {
      double megakernel_rate = 0.0;
      std::string megakernel_hash;
      for (size_t run = 0; run <= widths.size() * orders.size(); ++run) {
        RenderOverrides ov;
        ov.width = ov.height = cmd.size;
        ov.spp = cmd.spp;
        const uint32_t width = run > 0 ? widths[(run - 1) / orders.size()] : 0;
        const StreamOrder order = run > 0 ? orders[(run - 1) % orders.size()] : StreamOrder::Queue;
        if (run > 0) {
          ov.schedule = Schedule::Stream;
          ov.stream_width = width;
          ov.stream_order = order;
        }
        const Scene scene = load_scene(path, ov);
        RenderStats stats;
        Image image;
        const double seconds = median_seconds(cmd.repeats, [&] {
          stats = RenderStats{};
          image = render_cpu(scene, threads, stats);
        });
        const uint64_t rays = stats.rays.camera + stats.rays.secondary + stats.rays.shadow;
        const double rate = static_cast<double>(rays) / seconds / 1e6;
        const std::string name = std::filesystem::path(path).stem().string();
        if (run == 0) {
          megakernel_rate = rate;
          megakernel_hash = pixel_hash(image);
          std::printf("%-16s %7d %-10s %8s %10.2f %7s\n", name.c_str(), threads, "megakernel", "-", rate, "1.00");
          continue;
        }
        if (pixel_hash(image) != megakernel_hash)
          throw std::runtime_error(path + ": the stream schedule's image differs from the megakernel's");
        const StreamStats& s = stats.stream;
        std::printf("%-16s %7d %-10s %8u %10.2f %7.2f %9zu %9.1f %9llu %7llu %12.0f\n", name.c_str(), threads,
                    order == StreamOrder::Sorted ? "sorted" : "stream", width, rate, rate / megakernel_rate, s.bytes_per_state,
                    static_cast<double>(s.state_bytes) / 1e6, static_cast<unsigned long long>(s.largest_queue),
                    static_cast<unsigned long long>(s.waves),
                    s.waves ? static_cast<double>(s.shadow_rays) / static_cast<double>(s.waves) : 0.0);
      }
    }
  }
  std::printf(
      "ratio: stream Mrays/s over the megakernel's; sorted: the stream with --stream-order sorted; B/state: "
      "ray-state bytes per sample in flight\n");
  return 0;
}

const RegisterCommand kBenchScheduleCommand(
    {"bench", "schedule", "megakernel against stream schedule: Mrays/s, memory per ray in flight, queue sizes",
     [](CLI::App& app) {
       auto cmd = std::make_shared<BenchScheduleCommand>();
       app.add_option("scenes", cmd->scenes,
                      "scene files (default scenes/cornell-box-path.json and, when generated, scenes/large/bunny.json "
                      "and scenes/large/terrain.json)");
       app.add_option("--spp", cmd->spp, "samples per pixel (default 4)")->check(count_in(1, 4096));
       app.add_option("--size", cmd->size, "image width and height (default 128)")->check(count_in(1, 4096));
       app.add_option("--repeats", cmd->repeats, "runs per measurement; the median is kept (default 3)")
           ->check(count_in(1, 100));
       app.add_option("--threads", cmd->threads, "comma-separated thread counts (default 1,2)");
       app.add_option("--widths", cmd->widths, "comma-separated stream widths (default 4096,65536,262144)");
       app.add_option("--orders", cmd->orders, "comma-separated stream orders, queue and sorted (default both)");
       return [cmd] { return run_bench_schedule(*cmd); };
     }});

}  // namespace tracer
