// `tracer bench rays SCENE_OR_OBJ`: for each acceleration structure, build time, memory and
// node count, closest-hit throughput for the primary rays of a 512x512 pinhole camera and
// for 2^22 incoherent rays (origins uniform in the scene's box, directions uniform on the
// sphere), and any-hit throughput for shadow rays from the primary hits to a point above
// the scene; on all cores. A checksum of the hits shows every structure found the same.
// Every build time and rate is the median of --repeats runs (Embree's too; builds repeated
// until they fill 0.25 s where they are faster than that). With --device
// cuda, each structure has a second row: the same rays traced by the GPU stream schedule's
// closest-hit and shadow kernels (render/trace_cuda.h), kernel time only. Rows "bvh sorted"
// (and "bvh cuda sorted") trace each set in the order of its rays' keys (origin and direction,
// kernel/geom/ray_order_key.h), the sort timed with the trace.
#include <omp.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

#include "accel/acceleration.h"
#include "accel/bounds.h"
#include "accel/wide_bvh_builder.h"
#include "bench/bench_common.h"
#include "bench/embree_bench.h"
#include "bench/mesh_generators.h"
#include "render/ray_order_sort.h"
#include "bench/ray_sets.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "io/input_error.h"
#include "io/json_reader.h"
#include "kernel/accel/traverse_wide_bvh.h"
#include "options/enum_names.h"
#include "render/cpu_kernel.h"
#include "render/render_cuda.h"
#include "render/trace_cuda.h"
#include "scene/camera_setup.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"

namespace tracer {

struct BenchRaysCommand {
  std::string scene, accel, device = "cpu";
  uint32_t incoherent = 1u << 22, grid_resolution = 0, repeats = 3;
  int threads = 0;
};
namespace {

constexpr uint32_t kCamera = 512;

// An OBJ becomes a one-mesh scene; the camera frames the mesh in either case.
Scene load_bench_scene(const std::string& path, AccelKind accel, uint32_t grid_resolution) {
  RenderOverrides ov;
  ov.accel = accel;
  ov.width = ov.height = kCamera;
  ov.integrator = IntegratorKind::Whitted;
  if (grid_resolution) ov.grid_resolution = grid_resolution;
  const std::filesystem::path p(path);
  if (p.extension() != ".obj") return load_scene(path, ov);
  const std::string json = R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 1], "to": [0, 0, 0], "vfov": 45},
    "film": {"width": 512, "height": 512}, "materials": {"m": {"type": "lambert", "albedo": [0.7, 0.7, 0.7]}},
    "shapes": [{"type": "mesh", "file": )" +
                           Json(p.filename().string()).dump() + R"(, "material": "m"}]})";
  Scene scene = load_scene_text(json, (p.parent_path() / "bench-rays.json").string(), ov);
  const Bounds b = bounds_of_primitives(scene.primitives.data(), scene.primitives.size());
  CameraSpec spec;
  spec.to = (b.lo + b.hi) * 0.5f;
  spec.from = mesh_bench_eye(b.lo, b.hi);
  spec.up = {0, 1, 0};
  spec.vfov_degrees = kMeshBenchFov;
  spec.aperture = 0.0f;
  spec.focus_distance = length(spec.from - spec.to);
  scene.camera = make_camera(spec, kCamera, kCamera);
  return scene;
}

RaySets make_rays(const Scene& scene, uint32_t incoherent) {
  const Bounds b = bounds_of_primitives(scene.primitives.data(), scene.primitives.size());
  return make_primary_and_incoherent_rays(scene.camera, kCamera, kCamera, b.lo, b.hi, incoherent);
}

constexpr size_t kChunk = 1024;  // rays per call of a CPU kernel

// Runs `query(begin, count)` over [0, n) in chunks of kChunk on all threads, `repeats` times;
// returns the median Mrays/s.
double throughput(size_t n, int threads, uint32_t repeats, const std::function<void(size_t, size_t)>& query) {
  return median_of(repeats, [&] {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int64_t c = 0; c < static_cast<int64_t>((n + kChunk - 1) / kChunk); ++c) {
      const size_t begin = static_cast<size_t>(c) * kChunk;
      query(begin, std::min(kChunk, n - begin));
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return static_cast<double>(n) / s / 1e6;
  });
}

// Mrays/s of tracing `set` in the order of its rays' keys: the sort (render/ray_order_sort.h), a
// sorted copy of the rays, the trace in chunks on all threads (trace(rays, their indices in the
// set, count, answers)) and the answers put back in the set's order, all timed (the buffers are
// allocated before); the median of `repeats` runs.
template <class Answer, class Trace>
double sorted_throughput(const std::vector<Ray>& set, const RayOrderFrame& frame, int threads, uint32_t repeats,
                         std::vector<Answer>& answers, const Trace& trace) {
  const int64_t n = static_cast<int64_t>(set.size()), chunks = (n + kChunk - 1) / kChunk;
  CpuRaySorter sorter(set.size());
  std::vector<Ray> sorted(set.size());
  std::vector<Answer> sorted_answers(set.size());
  answers.resize(set.size());
  return median_of(repeats, [&] {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<uint32_t>& order = sorter.sort(set, frame, threads);
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static)
      for (int64_t i = 0; i < n; ++i) sorted[i] = set[order[i]];
#pragma omp for schedule(dynamic, 1)
      for (int64_t c = 0; c < chunks; ++c) {
        const int64_t begin = c * static_cast<int64_t>(kChunk);
        trace(&sorted[begin], &order[begin], static_cast<size_t>(std::min<int64_t>(kChunk, n - begin)),
              &sorted_answers[begin]);
      }
#pragma omp for schedule(static)
      for (int64_t i = 0; i < n; ++i) answers[order[i]] = sorted_answers[i];
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return static_cast<double>(n) / s / 1e6;
  });
}

// Seconds of one build of the scene's structure.
double one_build_seconds(const Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const Acceleration a = build_acceleration(scene.settings.accel, scene.primitives, scene.settings.grid_resolution);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The median of `repeats` builds of the scene's structure (more for a fast one), in seconds.
double build_seconds(const Scene& scene, uint32_t repeats) {
  return median_build_seconds(repeats, [&] { return one_build_seconds(scene); });
}

}  // namespace

static int run_bench_rays(const BenchRaysCommand& cmd) {
  const int threads = cmd.threads > 0 ? cmd.threads : omp_get_max_threads();
  std::vector<AccelKind> accels;
  if (cmd.accel.empty()) {
    accels = {AccelKind::Bvh, AccelKind::Lbvh, AccelKind::Kdtree, AccelKind::KdtreeMedian, AccelKind::Grid};
  } else {
    accels = parse_enum_list<AccelKind>(cmd.accel, "--accel " + cmd.accel);
  }
  // A GPU that is missing is said before any work (DeviceUnavailable, exit 2).
  const std::string gpu = cmd.device == "cuda" ? "; GPU " + cuda_device_description() : "";
  std::printf(
      "tracer bench rays %s: %d threads%s; primary: %ux%u pinhole, incoherent: %u rays, shadow: any-hit; "
      "medians of %u runs\n",
      cmd.scene.c_str(), threads, gpu.c_str(), kCamera, kCamera, cmd.incoherent, cmd.repeats);
  std::printf("%-14s %10s %10s %10s %10s | %10s %10s %10s | %s\n", "accel", "build s", "MB", "B/prim", "nodes",
              "primary", "incoherent", "shadow", "hits (checksum)");
  RaySets rays;
  uint64_t reference = 0;
  std::vector<Hit> reference_primary, reference_incoherent;
  double bvh_rates[3] = {0, 0, 0}, bvh_build = 0;
  std::string kernel_name;
  // Closest hits of the primary and the incoherent rays through `view` (into primary and
  // incoherent), and their Mrays/s into rates[0..1]; medians of `repeats` runs.
  const auto closest_rates = [&](const SceneView& view, const CpuKernelVariant& kernel, uint32_t repeats,
                                 std::vector<Hit>& primary, std::vector<Hit>& incoherent, double rates[2]) {
    primary.resize(rays.primary.size());
    incoherent.resize(rays.incoherent.size());
    const std::vector<float> no_limit(std::max(primary.size(), incoherent.size()), kInfinity);
    rates[0] = throughput(primary.size(), threads, repeats, [&](size_t i, size_t n) {
      kernel.trace_closest(view, &rays.primary[i], no_limit.data(), n, &primary[i]);
    });
    rates[1] = throughput(incoherent.size(), threads, repeats, [&](size_t i, size_t n) {
      kernel.trace_closest(view, &rays.incoherent[i], no_limit.data(), n, &incoherent[i]);
    });
  };
  // Any hit of the shadow rays (into occluded); the median Mrays/s of `repeats` runs.
  const auto shadow_rate = [&](const SceneView& view, const CpuKernelVariant& kernel, uint32_t repeats,
                               std::vector<uint8_t>& occluded) {
    occluded.assign(rays.shadow.size(), 0);
    return throughput(rays.shadow.size(), threads, repeats, [&](size_t i, size_t n) {
      kernel.trace_any(view, &rays.shadow[i], &rays.shadow_tmax[i], n, &occluded[i]);
    });
  };
  // A row's rates and checksum, which must equal the first structure's.
  const auto print_rates = [&](const std::string& label, const double rates[3], uint64_t sum) {
    std::printf("%10.2f %10.2f %10.2f | %016llx %s\n", rates[0], rates[1], rates[2],
                static_cast<unsigned long long>(sum), sum == reference ? "same" : "DIFFERENT");
    if (sum != reference)
      throw std::runtime_error(label + ": hits differ from " + enum_name(accels[0]) +
                               "'s (docs/determinism.md rule 4)");
  };
  // Traces every ray set through `view` with `kernel`; prints the row and checks the checksum.
  const auto measure = [&](const std::string& label, const Scene& scene, const SceneView& view,
                           const CpuKernelVariant& kernel, double rates[3], double build) {
    std::vector<Hit> primary, incoherent;
    closest_rates(view, kernel, cmd.repeats, primary, incoherent, rates);
    if (rays.shadow.empty()) {  // from each primary hit toward a point above the scene, once for all structures
      add_shadow_rays(view, shadow_light(scene.camera), primary, rays);
      reference_primary = primary;
      reference_incoherent = incoherent;
    }
    std::vector<uint8_t> occluded;
    rates[2] = shadow_rate(view, kernel, cmd.repeats, occluded);
    const uint64_t sum = ray_hits_checksum(primary, incoherent, occluded);
    if (reference == 0) reference = sum;
    if (build > 0)
      std::printf("%-14s %10.4f %10.1f %10.1f %10zu | ", label.c_str(), build, scene.report.accel_bytes / 1048576.0,
                  static_cast<double>(scene.report.accel_bytes) / static_cast<double>(scene.primitives.size()),
                  scene.report.accel.nodes + scene.report.accel.cells);
    else
      std::printf("%-14s %10s %10s %10s %10s | ", label.c_str(), "", "", "", "");
    print_rates(label, rates, sum);
  };
  // The row "bvh sorted": bvh's kernel with each set sorted by its rays' keys in `frame` first
  // (render/ray_order_sort.h), the sort and the copies timed with the trace.
  const auto measure_sorted = [&](const SceneView& view, const CpuKernelVariant& kernel, const RayOrderFrame& frame) {
    const std::vector<float> no_limit(kChunk, kInfinity);
    const auto closest = [&](const Ray* r, const uint32_t*, size_t n, Hit* hits) {
      kernel.trace_closest(view, r, no_limit.data(), n, hits);
    };
    const auto any = [&](const Ray* r, const uint32_t* index, size_t n, uint8_t* occluded) {
      float tmax[kChunk];
      for (size_t k = 0; k < n; ++k) tmax[k] = rays.shadow_tmax[index[k]];
      kernel.trace_any(view, r, tmax, n, occluded);
    };
    std::vector<Hit> primary, incoherent;
    std::vector<uint8_t> occluded;
    const double rates[3] = {sorted_throughput(rays.primary, frame, threads, cmd.repeats, primary, closest),
                             sorted_throughput(rays.incoherent, frame, threads, cmd.repeats, incoherent, closest),
                             sorted_throughput(rays.shadow, frame, threads, cmd.repeats, occluded, any)};
    std::printf("%-14s %10s %10s %10s %10s | ", "bvh sorted", "", "", "", "");
    print_rates("bvh sorted", rates, ray_hits_checksum(primary, incoherent, occluded));
  };
  // The GPU's row for a structure: its trace variant's kernels (kernel/accel/trace_variants.h)
  // on the tree `tree` names (render/device_bvh.h) where the structure is bvh or lbvh; with a
  // `sorted` frame each set sorted on the device before its launch, the sort timed with it.
  const auto measure_cuda = [&](const std::string& label, const Scene& scene, DeviceBvh tree,
                                std::optional<RayOrderFrame> sorted = std::nullopt) {
    CudaRayTracer device(scene, scene.view(), tree);
    std::vector<Hit> primary, incoherent;
    std::vector<uint8_t> occluded;
    const double seconds[3] = {device.closest(rays.primary, primary, cmd.repeats, sorted),
                               device.closest(rays.incoherent, incoherent, cmd.repeats, sorted),
                               device.any(rays.shadow, rays.shadow_tmax, occluded, cmd.repeats, sorted)};
    const uint64_t sum = ray_hits_checksum(primary, incoherent, occluded);
    std::printf("%-14s %10s %10s %10s %10s | %10.2f %10.2f %10.2f | %016llx %s (trace %s)\n", label.c_str(), "", "", "",
                "", rays.primary.size() / seconds[0] / 1e6, rays.incoherent.size() / seconds[1] / 1e6,
                rays.shadow.size() / seconds[2] / 1e6, static_cast<unsigned long long>(sum),
                sum == reference ? "same" : "DIFFERENT", device.variant());
    if (sum != reference) throw std::runtime_error(label + ": hits differ from the CPU's (docs/determinism.md rule 1)");
  };
  for (const AccelKind accel : accels) {
    const Scene scene = load_bench_scene(cmd.scene, accel, cmd.grid_resolution);
    if (rays.primary.empty()) {
      rays = make_rays(scene, cmd.incoherent);
      std::printf("(%zu primitives)\n", scene.primitives.size());
    }
    double rates[3];
    const SceneView view = scene.view();
    const CpuKernelVariant& kernel = cpu_kernel_for(view.features);
    kernel_name = cpu_kernel_name(kernel);
    const double build = build_seconds(scene, cmd.repeats);
    measure(enum_name(accel), scene, view, kernel, accel == AccelKind::Bvh ? bvh_rates : rates, build);
    if (cmd.device == "cuda") measure_cuda(std::string(enum_name(accel)) + " cuda", scene, DeviceBvh::Pairs);
    if (accel != AccelKind::Bvh) continue;
    // The box the sorted rows' keys place origins in: the tree's root (kernel/geom/ray_order_key.h).
    const std::optional<RayOrderFrame> frame =
        scene.bvh_nodes.empty() ? std::nullopt
                                : std::optional(ray_order_frame(scene.bvh_nodes[0].lo, scene.bvh_nodes[0].hi));
    if (cmd.device == "cuda") {
      if (frame) measure_cuda("bvh cuda sorted", scene, DeviceBvh::Pairs, frame);
      measure_cuda("bvh nodes cuda", scene, DeviceBvh::Binary);
      measure_cuda("bvh8 cuda", scene, DeviceBvh::Wide);
      std::printf("(bvh8 cuda: the 8-wide tree needs %u stack entries, the variant holds %d)\n",
                  wide_bvh_stack_need(scene.wide_nodes), kWideVariantStackSize);
    }
    bvh_build = build;
    for (const CpuKernelVariant* other : cpu_kernels_per_isa(view.features))  // the instruction sets compared
      if (other != &kernel) measure(std::string("bvh ") + other->isa, scene, view, *other, rates, 0);
    SceneView binary = view;  // the same tree walked two children at a time, as the GPU walks it
    binary.wide_node_count = 0;
    measure("bvh (binary)", scene, binary, kernel, rates, 0);
    if (frame) measure_sorted(view, kernel, *frame);
  }
  std::printf(
      "(CPU kernel %s; a row \"bvh ISA\" runs the same tree with that instruction set's kernel, \"bvh "
      "sorted\" bvh with each set sorted by origin and direction first, the sort timed with it%s)\n",
      kernel_name.c_str(),
      cmd.device == "cuda"
          ? "; a row \"ACCEL cuda\" the GPU's stream kernels, kernel time only, on bvh's and lbvh's "
            "pair records where the scene is all triangles; \"bvh cuda sorted\" the same with each set sorted "
            "on the device by origin and direction first, the sort timed with it; \"bvh nodes cuda\" on "
            "bvh's binary nodes, "
            "\"bvh8 cuda\" on its 8-wide tree"
          : "");
  const Scene embree_scene = load_bench_scene(cmd.scene, AccelKind::None, 0);
  const bool triangles_only = std::all_of(embree_scene.primitives.begin(), embree_scene.primitives.end(),
                                          [](const Primitive& p) { return p.kind == ShapeKind::Triangle; });
  if (embree_available() && triangles_only) {
    const Scene& scene = embree_scene;
    const bool compared = bvh_rates[0] > 0;  // bvh is among the structures measured
    const Scene bvh_scene = compared ? load_bench_scene(cmd.scene, AccelKind::Bvh, cmd.grid_resolution) : Scene{};
    std::function<double()> our_build;
    if (compared) our_build = [&] { return one_build_seconds(bvh_scene); };
    const EmbreeRow e = embree_bench(scene, rays.primary, rays.incoherent, rays.shadow, rays.shadow_tmax,
                                     reference_primary, reference_incoherent, threads, cmd.repeats, our_build);
    std::printf(
        "%-14s %10.4f %10.1f %10.1f %10s | %10.2f %10.2f %10.2f | %.4f%% of closest hits on the same primitive\n",
        "embree 3", e.build_seconds, e.megabytes,
        e.megabytes * 1048576.0 / static_cast<double>(scene.primitives.size()), "-", e.primary, e.incoherent, e.shadow,
        100.0 * e.same_primitive);
    if (compared) {
      std::printf("%-14s %10.2f %10s %10s %10s | %10.2f %10.2f %10.2f |\n", "bvh / embree", bvh_build / e.build_seconds,
                  "", "", "", bvh_rates[0] / e.primary, bvh_rates[1] / e.incoherent, bvh_rates[2] / e.shadow);
      // Each rate's ratio again from one run of each renderer back to back, --repeats times: a
      // machine whose speed drifts between the two rows' runs moves both halves alike.
      const SceneView view = bvh_scene.view();
      const CpuKernelVariant& kernel = cpu_kernel_for(view.features);
      std::vector<double> paired[3];
      std::vector<Hit> primary, incoherent;
      std::vector<uint8_t> occluded;
      for (uint32_t r = 0; r < cmd.repeats; ++r) {
        double ours[3];
        closest_rates(view, kernel, 1, primary, incoherent, ours);
        ours[2] = shadow_rate(view, kernel, 1, occluded);
        const EmbreeRow one = embree_bench(scene, rays.primary, rays.incoherent, rays.shadow, rays.shadow_tmax,
                                           reference_primary, reference_incoherent, threads, 1);
        paired[0].push_back(ours[0] / one.primary);
        paired[1].push_back(ours[1] / one.incoherent);
        paired[2].push_back(ours[2] / one.shadow);
      }
      std::printf("%-14s %10.2f %10s %10s %10s | %10.2f %10.2f %10.2f |\n", "paired ratio", e.paired_build, "", "", "",
                  median_value(paired[0]), median_value(paired[1]), median_value(paired[2]));
      std::printf(
          "(bvh / embree: the two rows' medians over each other; paired ratio: the median of %u ratios, "
          "each of one run of bvh and one of Embree timed back to back; for the build, of pairs of builds, "
          "each started 20 ms after the last, as a scene's one build starts from idle threads)\n",
          cmd.repeats);
    }
  } else if (embree_available()) {  // the rows above are the answer; the comparison is for meshes
    std::printf("(no Embree row: Embree is compared on scenes of triangles alone; this one holds other shapes)\n");
  } else {
    std::printf("(no Embree row: this build has no Embree adapter; install libembree-dev and reconfigure)\n");
  }
  std::printf("throughput in Mrays/s\n");
  return 0;
}

const RegisterCommand kBenchRaysCommand(
    {"bench", "rays", "build time, memory and Mrays/s of each acceleration structure", [](CLI::App& app) {
       auto cmd = std::make_shared<BenchRaysCommand>();
       app.add_option("scene", cmd->scene, "scene file (JSON) or OBJ mesh")->required();
       app.add_option("--accel", cmd->accel, "comma-separated structures (default bvh,lbvh,kdtree,kdtree-median,grid)");
       app.add_option("--rays", cmd->incoherent, "incoherent rays (default 2^22)")->check(count_in(1, 1u << 25));
       app.add_option("--grid-resolution", cmd->grid_resolution,
                      "grid cells along the longest axis (default: by density)")
           ->check(count_in(1, 1024));
       app.add_option("--repeats", cmd->repeats,
                      "runs per measurement, the median kept (default 3); a build faster than 0.25 s is repeated until "
                      "its runs fill that")
           ->check(count_in(1, 100));
       app.add_option("--device", cmd->device, "cpu, or cuda: a GPU row per structure beside the CPU's (default cpu)")
           ->check(CLI::IsMember({"cpu", "cuda"}));
       add_threads_option(app, cmd->threads);
       return [cmd] { return run_bench_rays(*cmd); };
     }});

}  // namespace tracer
