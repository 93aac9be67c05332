#include "bench/watertight_probe.h"

#include <omp.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>
#include <utility>

#include "accel/bounds.h"
#include "io/input_error.h"
#include "kernel/accel/trace.h"
#include "scene/scene_loader.h"

namespace tracer {
namespace {

using Key = std::pair<uint32_t, uint32_t>;  // an edge by its two endpoints' vertex numbers

// Vertex numbers by bit-identical position, and every edge with its triangle count.
struct MeshTopology {
  std::vector<Vec3> vertices;
  std::map<Key, uint32_t> edges;
};

MeshTopology topology(const Scene& mesh) {
  MeshTopology t;
  std::map<std::tuple<uint32_t, uint32_t, uint32_t>, uint32_t> number;
  const auto vertex = [&](Vec3 p) {
    const auto key = std::make_tuple(bits_of(p.x), bits_of(p.y), bits_of(p.z));
    const auto [it, inserted] = number.emplace(key, static_cast<uint32_t>(t.vertices.size()));
    if (inserted) t.vertices.push_back(p);
    return it->second;
  };
  for (const Primitive& p : mesh.primitives) {
    if (p.kind != ShapeKind::Triangle) continue;
    const uint32_t v[3] = {vertex(p.a), vertex(p.b), vertex(p.c)};
    for (int i = 0; i < 3; ++i) ++t.edges[{std::min(v[i], v[(i + 1) % 3]), std::max(v[i], v[(i + 1) % 3])}];
  }
  return t;
}

// Crossings of the ray with the mesh, every triangle tested (watertight test).
int crossings(const Scene& mesh, const Ray& ray) {
  const RayShear shear = make_ray_shear(ray.dir);
  int n = 0;
  for (const Primitive& p : mesh.primitives) {
    float t, b0, b1, b2;
    if (p.kind == ShapeKind::Triangle && intersect_triangle(p.a, p.b, p.c, ray, shear, 0.0f, kInfinity, t, b0, b1, b2))
      ++n;
  }
  return n;
}

}  // namespace

Scene load_probe_mesh(const std::string& obj_path, TriangleTest triangle_test) {
  RenderOverrides ov;
  ov.triangle_test = triangle_test;
  const std::filesystem::path p = std::filesystem::absolute(obj_path);
  const std::string json = R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 1], "to": [0, 0, 0], "vfov": 45},
    "film": {"width": 1, "height": 1}, "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "mesh", "file": )" +
                           nlohmann::json(p.filename().string()).dump() + R"(, "material": "m"}]})";
  return load_scene_text(json, (p.parent_path() / "watertight-probe.json").string(), ov);
}

std::vector<Vec3> inside_points(const Scene& mesh) {
  const Bounds b = bounds_of_primitives(mesh.primitives.data(), mesh.primitives.size());
  const Vec3 centre = (b.lo + b.hi) * 0.5f, step = (b.hi - b.lo) * 0.125f;
  std::vector<Vec3> inside;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Vec3 o = centre + Vec3{step.x * dx, step.y * dy, step.z * dz};
        const Vec3 axes[3] = {normalize(Vec3{1, 0.01f, 0.02f}), normalize(Vec3{0.02f, 1, 0.01f}),
                              normalize(Vec3{0.01f, 0.02f, 1})};
        bool odd = true;
        for (const Vec3& d : axes) odd = odd && crossings(mesh, {o, d}) % 2 == 1 && crossings(mesh, {o, -d}) % 2 == 1;
        if (odd) inside.push_back(o);
      }
  if (inside.empty()) throw InputError(mesh.file + ": found no point inside the mesh near the centre of its bounds");
  return inside;
}

WatertightProbe probe_watertight(const Scene& mesh, const std::vector<Vec3>& origins, uint32_t edge_points,
                                 int threads) {
  const MeshTopology topo = topology(mesh);
  WatertightProbe r;
  for (const auto& [edge, count] : topo.edges) r.open_edges += count != 2;
  std::vector<Vec3> targets = topo.vertices;
  for (const auto& [edge, count] : topo.edges) {
    const Vec3 a = topo.vertices[edge.first], d = topo.vertices[edge.second] - a;
    for (uint32_t k = 1; k <= edge_points; ++k)
      targets.push_back(a + d * (static_cast<float>(k) / static_cast<float>(edge_points + 1)));
  }
  const SceneView view = mesh.view();
  const int64_t n = static_cast<int64_t>(targets.size());
  uint64_t escapes = 0;
  const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads()) reduction(+ : escapes)
  for (int64_t i = 0; i < n; ++i)
    for (const Vec3& o : origins) {
      const Vec3 d = normalize(targets[static_cast<size_t>(i)] - o);
      escapes += trace_closest(view, {o, d}, kInfinity).prim == kNoHit;
    }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.rays = static_cast<uint64_t>(n) * origins.size();
  r.escapes = escapes;
  return r;
}

}  // namespace tracer
