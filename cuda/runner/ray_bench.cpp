#include "ray_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "accel/bvh_builder.h"
#include "accel/wide_bvh_builder.h"
#include "bench/mesh_generators.h"
#include "bench/ray_sets.h"
#include "io/input_error.h"
#include "kernel/accel/trace.h"
#include "parity/parallel_for.h"
#include "render/trace_cuda.h"

namespace tracer {
namespace {

constexpr uint32_t kIncoherentRays = 1u << 20;

struct TracedRays {
  std::vector<Hit> primary, incoherent;
  std::vector<uint8_t> occluded;
  double seconds[3] = {0, 0, 0};  // primary, incoherent, shadow
};

// The best wall time of `repeats` runs of fn().
template <class Fn>
double best_seconds(uint32_t repeats, Fn fn) {
  double best = 0;
  for (uint32_t r = 0; r < std::max(1u, repeats); ++r) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = r == 0 ? s : std::min(best, s);
  }
  return best;
}

// Every ray set traced on the CPU's threads by the full code (the 8-wide tree where `view` holds one).
TracedRays trace_on_cpu(const SceneView& view, const RaySets& rays, unsigned threads, uint32_t repeats) {
  TracedRays t;
  t.primary.resize(rays.primary.size());
  t.incoherent.resize(rays.incoherent.size());
  t.occluded.resize(rays.shadow.size());
  t.seconds[0] = best_seconds(repeats, [&] {
    parallel_for(rays.primary.size(), threads,
                 [&](size_t i) { t.primary[i] = trace_closest(view, rays.primary[i], kInfinity); });
  });
  t.seconds[1] = best_seconds(repeats, [&] {
    parallel_for(rays.incoherent.size(), threads,
                 [&](size_t i) { t.incoherent[i] = trace_closest(view, rays.incoherent[i], kInfinity); });
  });
  t.seconds[2] = best_seconds(repeats, [&] {
    parallel_for(rays.shadow.size(), threads,
                 [&](size_t i) { t.occluded[i] = trace_any(view, rays.shadow[i], rays.shadow_tmax[i]) ? 1 : 0; });
  });
  return t;
}

void print_row(const std::string& name, const RaySets& rays, const TracedRays& t, uint64_t sum, uint64_t reference,
               const std::string& note) {
  std::printf("%-10s %-34s %10.1f %10.1f %10.1f  %016llx %s%s\n", "rays", name.c_str(),
              rays.primary.size() / t.seconds[0] / 1e6, rays.incoherent.size() / t.seconds[1] / 1e6,
              rays.shadow.size() / t.seconds[2] / 1e6, static_cast<unsigned long long>(sum),
              sum == reference ? "same" : "DIFFERENT", note.c_str());
  std::fflush(stdout);
}

}  // namespace

SceneBundle with_generated_mesh(SceneBundle bundle, const std::string& kind, uint32_t triangles) {
  const std::vector<MeshTriangle> mesh = generate_mesh(kind, triangles);
  if (bundle.arrays.materials.empty()) throw InputError("the bundle has no material for the mesh");
  SceneArrays& a = bundle.arrays;
  a.primitives.clear();
  for (const MeshTriangle& t : mesh) a.primitives.push_back({ShapeKind::Triangle, 0, -1, 0.0f, t.p[0], t.p[1], t.p[2]});
  a.triangle_shading.clear();
  a.unbounded.clear();
  a.bounded.clear();
  a.bvh_nodes = build_sah_bvh(a.primitives, a.bounded);
  a.wide_nodes.clear();
  a.triangle_blocks.clear();
  a.light_table.clear();
  a.light_of_prim.clear();
  a.mirror_prims.clear();
  return bundle;
}

void run_ray_bench(const SceneBundle& bundle, const std::string& label, bool gpu, unsigned threads, uint32_t repeats) {
  if (bundle.scalars.settings.accel != AccelKind::Bvh || bundle.arrays.bvh_nodes.empty())
    throw InputError(label + ": the rays table traces bvh's two trees; this bundle's structure is not bvh");
  SceneArrays arrays = bundle.arrays;
  if (arrays.wide_nodes.empty()) {
    WideBvh wide = collapse_to_wide_bvh(arrays.bvh_nodes, arrays.bounded, arrays.primitives);
    arrays.wide_nodes = std::move(wide.nodes);
    arrays.triangle_blocks = std::move(wide.blocks);
  }
  SceneView view = bundle.scalars;
  point_view_at(view, arrays);
  const RenderSettings& rs = view.settings;
  const BvhNode& root = arrays.bvh_nodes[0];
  RaySets rays = make_primary_and_incoherent_rays(view.camera, rs.width, rs.height, root.lo, root.hi, kIncoherentRays);

  // The shadow rays start at the primary hits.
  std::vector<Hit> primary_hits(rays.primary.size());
  parallel_for(rays.primary.size(), threads,
               [&](size_t i) { primary_hits[i] = trace_closest(view, rays.primary[i], kInfinity); });
  add_shadow_rays(view, shadow_light(view.camera), primary_hits, rays);

  // The CPU, the best of at most 3 runs: the full code on the 8-wide tree (the reference), and on the binary tree.
  const uint32_t cpu_repeats = std::min(repeats, 3u);
  const TracedRays cpu = trace_on_cpu(view, rays, threads, cpu_repeats);
  const uint64_t reference = ray_hits_checksum(cpu.primary, cpu.incoherent, cpu.occluded);
  print_row(label + " cpu bvh8", rays, cpu, reference, reference,
            "  (" + std::to_string(threads) + " threads; " + std::to_string(rays.primary.size()) + " primary, " +
                std::to_string(rays.incoherent.size()) + " incoherent, " + std::to_string(rays.shadow.size()) +
                " shadow rays)");
  SceneView binary = view;
  binary.wide_node_count = 0;
  const TracedRays cpu_binary = trace_on_cpu(binary, rays, threads, cpu_repeats);
  const uint64_t binary_sum = ray_hits_checksum(cpu_binary.primary, cpu_binary.incoherent, cpu_binary.occluded);
  print_row(label + " cpu bvh", rays, cpu_binary, binary_sum, reference, "");
  if (binary_sum != reference) throw std::runtime_error(label + ": the binary tree's hits differ from the wide tree's");
  if (!gpu) return;
  // The pair records twice: the sets as made, and each sorted on the device before its launch
  // (cuda/ray_order_gpu.h), the sort timed with the trace.
  const struct {
    DeviceBvh tree;
    const char* name;
    bool sorted;
  } trees[] = {{DeviceBvh::Binary, " bvh nodes cuda", false},
               {DeviceBvh::Pairs, " bvh cuda", false},
               {DeviceBvh::Pairs, " bvh cuda sorted", true},
               {DeviceBvh::Wide, " bvh8 cuda", false}};
  const RayOrderFrame frame = ray_order_frame(root.lo, root.hi);
  for (const auto& [tree, tree_name, sorted] : trees) {
    CudaRayTracer device(arrays, view, tree);
    const std::optional<RayOrderFrame> order = sorted ? std::optional(frame) : std::nullopt;
    TracedRays t;
    t.seconds[0] = device.closest(rays.primary, t.primary, repeats, order);
    t.seconds[1] = device.closest(rays.incoherent, t.incoherent, repeats, order);
    t.seconds[2] = device.any(rays.shadow, rays.shadow_tmax, t.occluded, repeats, order);
    const uint64_t sum = ray_hits_checksum(t.primary, t.incoherent, t.occluded);
    const std::string name = label + tree_name;
    char note[160];
    std::snprintf(note, sizeof note, "  (trace %s; %.1fx, %.1fx, %.1fx the CPU)", device.variant(),
                  cpu.seconds[0] / t.seconds[0], cpu.seconds[1] / t.seconds[1], cpu.seconds[2] / t.seconds[2]);
    std::string notes = note;
    if (sorted) {
      std::snprintf(note, sizeof note, "  (the sorts alone %.3f / %.3f / %.3f ms)",
                    device.sort(rays.primary, frame, repeats) * 1e3, device.sort(rays.incoherent, frame, repeats) * 1e3,
                    device.sort(rays.shadow, frame, repeats) * 1e3);
      notes += note;
    }
    print_row(name, rays, t, sum, reference, notes);
    if (sum != reference) throw std::runtime_error(name + ": hits differ from the CPU's (docs/determinism.md rule 1)");
  }
}

}  // namespace tracer
