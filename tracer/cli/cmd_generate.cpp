// `tracer generate KIND -o OUT.obj`: a deterministic procedural mesh (bench/mesh_generators.h)
// for the benchmarks and the large-scene tests.
#include <cstdio>
#include <filesystem>

#include "bench/mesh_generators.h"
#include "cli/command_registry.h"
#include "io/output_paths.h"

namespace tracer {
namespace {

struct GenerateCommand {
  std::string kind, output;
  uint32_t triangles = 100000;
};

static int run_generate(const GenerateCommand& cmd) {
  check_output_location(cmd.output, "-o");
  const std::vector<MeshTriangle> mesh = generate_mesh(cmd.kind, cmd.triangles);
  write_obj(mesh, cmd.output);
  std::printf("wrote %s: %zu triangles\n", std::filesystem::absolute(cmd.output).string().c_str(), mesh.size());
  return 0;
}

}  // namespace

const RegisterCommand kGenerateCommand(
    {"", "generate", "write a deterministic procedural mesh as OBJ", [](CLI::App& app) {
       auto cmd = std::make_shared<GenerateCommand>();
       app.add_option("kind", cmd->kind, "terrain, sphere, boxes, cubes, mixed, icosphere or cube")->required();
       app.add_option("--triangles", cmd->triangles, "target triangle count (default 100000)")
           ->check(count_in(1, 1u << 24));
       app.add_option("-o,--output", cmd->output, "OBJ file")->required();
       return [cmd] { return run_generate(*cmd); };
     }});

}  // namespace tracer
