// `tracer info SCENE`: what the loader made of a scene: shapes and primitives, materials and
// lights, the feature mask, a glTF file's contents and what it left out, the acceleration
// structure and how long loading took, and the trace variant the GPU's stream schedule runs.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "cli/command_registry.h"
#include "kernel/accel/trace_variants.h"
#include "options/enum_names.h"
#include "render/device_bvh.h"
#include "scene/scene_loader.h"

namespace tracer {
namespace {

using Clock = std::chrono::steady_clock;

// The background's type and, for a map, its size and the cells sampling it as a light.
void print_background(const Scene& scene) {
  const Background& bg = scene.background;
  std::printf("background %s", enum_name(bg.kind));
  const uint32_t texture = bg.kind == BackgroundKind::Environment ? bg.map
                           : bg.kind == BackgroundKind::Cubemap   ? bg.faces[0]
                                                                  : kNoTexture;
  if (texture != kNoTexture)
    std::printf(" (%ux%u texels%s)", scene.textures[texture].width, scene.textures[texture].height,
                bg.kind == BackgroundKind::Cubemap ? " a face" : "");
  if (scene.environment_light != kNoHit)
    std::printf(", a light of %ux%u cells%s", scene.sky_cell_columns, scene.sky_cell_rows,
                bg.kind == BackgroundKind::Cubemap ? " a face" : "");
  std::printf("\n");
}

static int run_info(const std::string& scene_path, const std::optional<std::string>& environment) {
  const auto t = Clock::now();
  RenderOverrides overrides;
  overrides.environment = environment;
  const Scene scene = load_scene(scene_path, overrides);
  const double seconds = std::chrono::duration<double>(Clock::now() - t).count();
  std::printf("scene      %s\n", scene_path.c_str());
  std::printf("shapes    ");
  for (const auto& [type, count] : scene.report.shape_counts) std::printf(" %s: %u", type.c_str(), count);
  uint32_t by_kind[4] = {};
  for (const Primitive& p : scene.primitives) ++by_kind[static_cast<int>(p.kind)];
  std::printf("\nprimitives %zu (spheres %u, planes %u, triangles %u, quads %u)\n", scene.primitives.size(), by_kind[0],
              by_kind[1], by_kind[2], by_kind[3]);
  if (scene.report.degenerate_triangles > 0)
    std::printf("left out   %u mesh triangles of zero area\n", scene.report.degenerate_triangles);
  std::printf("materials  %zu, declared lights %zu", scene.materials.size(), scene.lights.size());
#define TRACER_INFO_LIGHT_COUNT(Kind, type)                                                   \
  if (const long n = std::count_if(scene.lights.begin(), scene.lights.end(),                  \
                                   [](const Light& l) { return l.kind == LightKind::Kind; }); \
      n > 0)                                                                                  \
    std::printf(", %s %ld", type, n);
  TRACER_DECLARED_LIGHT_KINDS(TRACER_INFO_LIGHT_COUNT)
#undef TRACER_INFO_LIGHT_COUNT
  std::printf("\n");
  print_background(scene);
  if (!scene.mirror_prims.empty())
    std::printf(
        "mirrors    %zu flat mirrors, the lights seen in them sampled as mirror images (render.mirror_images)\n",
        scene.mirror_prims.size());
  std::printf("features  ");
  for (const std::string& f : feature_names(scene.features)) std::printf(" %s", f.c_str());
  for (const std::string& line : scene.report.gltf) std::printf("\ngltf       %s", line.c_str());
  const AccelSummary& accel = scene.report.accel;
  const std::string size = scene.settings.accel == AccelKind::Grid ? std::to_string(accel.cells) + " cells"
                                                                   : std::to_string(accel.nodes) + " nodes";
  std::printf("\naccel      %s: %s over %zu bounded primitives, %zu unbounded; load and build %.3f s\n",
              accel.name.c_str(), size.c_str(), scene.bounded.size(), scene.unbounded.size(), seconds);
  SceneView gpu_view = scene.view();  // what `render --device cuda` uploads: the binary tree alone
  gpu_view.wide_node_count = 0;
  std::printf("gpu trace  %s (the stream schedule's closest-hit and shadow kernels, docs/cuda.md)\n",
              trace_variant_name(device_trace_variant(gpu_view)));
  return 0;
}

}  // namespace

const RegisterCommand kInfoCommand(
    {"", "info", "primitive counts, feature mask and acceleration stats", [](CLI::App& app) {
       auto scene = std::make_shared<std::string>();
       auto environment = std::make_shared<std::optional<std::string>>();
       app.add_option("scene", *scene, "scene file (JSON), or a glTF 2.0 file")->required();
       app.add_option("--environment", *environment, "an equirectangular image as the background, as render's");
       return [scene, environment] { return run_info(*scene, *environment); };
     }});

}  // namespace tracer
