// `tracer bundle SCENE [render options] -o NAME.bundle`: the scene loaded and its
// acceleration structure built as for `render`, then every array the kernel reads, the
// view's scalars and the sample range written as one scene bundle (bundle/scene_bundle.h)
// for the self-contained GPU runner.
#include <cstdio>
#include <filesystem>

#include "bundle/scene_bundle.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "io/input_error.h"
#include "io/output_batch.h"
#include "io/output_paths.h"
#include "io/text_file.h"
#include "render/partial_file.h"
#include "scene/scene_loader.h"

namespace tracer {

static int run_bundle(const RenderCommand& cmd) {
  const std::filesystem::path out(cmd.output);
  check_output_location(cmd.output, "-o");
  if (out.extension() != ".bundle") throw InputError(cmd.output + ": name the bundle NAME.bundle");
  const std::string text = read_text_file(cmd.scene, "scene file");
  const Scene scene = load_scene_text(text, cmd.scene, scene_overrides(cmd));
  refuse_outputs_naming_inputs({{cmd.output, "-o"}}, scene.files_read());
  const uint32_t spp = scene.settings.spp;
  if (!cmd.samples.empty() && adaptive_render(scene.settings))
    throw InputError(cmd.scene +
                     ": --samples: an adaptive render (noise_threshold, target_error) decides its samples "
                     "from all of them, so it cannot be split into sample ranges; bundle it whole");
  const SampleRange range = cmd.samples.empty() ? SampleRange{0, spp} : parse_sample_range(cmd.samples, spp);
  const SceneBundle bundle = make_scene_bundle(scene, scene.view(), range, cmd.scene);
  const std::string bytes = encode_bundle(encode_scene_bundle(bundle));
  write_file_atomically(cmd.output, bytes);
  std::printf("wrote %s (%zu bytes: %ux%u, samples [%u, %u), %zu primitives)\n", cmd.output.c_str(), bytes.size(),
              scene.settings.width, scene.settings.height, range.begin, range.end, scene.primitives.size());
  return 0;
}

const RegisterCommand kBundleCommand(
    {"", "bundle", "write what the kernel reads for one render as a scene bundle for tracer-gpu", [](CLI::App& app) {
       auto cmd = std::make_shared<RenderCommand>();
       add_scene_options(app, *cmd);
       app.add_option("-o,--output", cmd->output, "output bundle, NAME.bundle")->required();
       return [cmd] { return run_bundle(*cmd); };
     }});

}  // namespace tracer
