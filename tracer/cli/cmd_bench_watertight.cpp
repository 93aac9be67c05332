// `tracer bench watertight [OBJ...]`: the speed/accuracy trade of the ray/triangle test on
// closed meshes. For each mesh, rays from points inside aimed at every vertex and along
// every edge (watertight_probe.h), traced with the watertight test and with
// Moller-Trumbore: the rays that escape through cracks, and Mrays/s. Without arguments it
// generates an icosphere and a grid cube, and adds scenes/generated/bunny.obj when present.
#include <unistd.h>
#include <cstdio>
#include <filesystem>

#include "bench/mesh_generators.h"
#include "bench/watertight_probe.h"
#include "cli/command_registry.h"
#include "cli/commands.h"

namespace tracer {

struct BenchWatertightCommand {
  std::vector<std::string> meshes;  // closed OBJ meshes; none: a generated icosphere and cube (and the bunny)
  uint32_t edge_points = 16;
  int threads = 0;
};

static int run_bench_watertight(const BenchWatertightCommand& cmd) {
  std::vector<std::string> meshes = cmd.meshes;
  const auto temp = std::filesystem::temp_directory_path() / ("tracer-watertight-" + std::to_string(getpid()));
  if (meshes.empty()) {
    std::filesystem::create_directories(temp);
    for (const char* kind : {"icosphere", "cube"}) {
      const std::string path = (temp / (std::string(kind) + ".obj")).string();
      write_obj(generate_mesh(kind, 20480), path);
      meshes.push_back(path);
    }
    if (std::filesystem::exists("scenes/generated/bunny.obj")) meshes.push_back("scenes/generated/bunny.obj");
  }
  std::printf(
      "tracer bench watertight: rays from points inside each closed mesh to every vertex and %u points of every edge\n",
      cmd.edge_points);
  std::printf("%-28s %9s %6s %10s | %12s %9s | %12s %9s\n", "mesh", "triangles", "open", "rays", "watertight",
              "Mrays/s", "moller-trumbore", "Mrays/s");
  for (const std::string& path : meshes) {
    WatertightProbe result[2];
    uint32_t triangles = 0;
    for (int k = 0; k < 2; ++k) {
      const Scene mesh = load_probe_mesh(path, k == 0 ? TriangleTest::Watertight : TriangleTest::MollerTrumbore);
      triangles = static_cast<uint32_t>(mesh.primitives.size());
      result[k] = probe_watertight(mesh, inside_points(mesh), cmd.edge_points, cmd.threads);
    }
    const auto mrays = [](const WatertightProbe& p) { return p.seconds > 0 ? p.rays / p.seconds / 1e6 : 0.0; };
    std::printf("%-28s %9u %6u %10llu | %12llu %9.1f | %15llu %9.1f\n", std::filesystem::path(path).filename().c_str(),
                triangles, result[0].open_edges, static_cast<unsigned long long>(result[0].rays),
                static_cast<unsigned long long>(result[0].escapes), mrays(result[0]),
                static_cast<unsigned long long>(result[1].escapes), mrays(result[1]));
  }
  std::filesystem::remove_all(temp);
  return 0;
}

const RegisterCommand kBenchWatertightCommand(
    {"bench", "watertight", "rays that escape closed meshes through cracks: watertight test vs Moller-Trumbore",
     [](CLI::App& app) {
       auto cmd = std::make_shared<BenchWatertightCommand>();
       app.add_option("meshes", cmd->meshes,
                      "closed OBJ meshes (default: a generated icosphere and cube, and scenes/generated/bunny.obj)");
       app.add_option("--edge-points", cmd->edge_points, "points aimed at along every edge (default 16)")
           ->check(count_in(1, 4096));
       add_threads_option(app, cmd->threads);
       return [cmd] { return run_bench_watertight(*cmd); };
     }});

}  // namespace tracer
