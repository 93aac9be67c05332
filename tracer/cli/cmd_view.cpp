// `tracer view SCENE`: a page on 127.0.0.1 showing the scene as it renders, with a movable
// camera (docs/viewer.md).
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "cli/command_registry.h"
#include "cli/commands.h"
#include "io/input_error.h"
#include "io/output_paths.h"
#include "io/text_file.h"
#include "render/render_cuda.h"
#include "scene/gltf_file.h"
#include "view/view_server.h"
#include "view/view_session.h"

namespace tracer {
namespace {

struct ViewCommand {
  RenderCommand render;
  int port = 0;
  std::string bind = "127.0.0.1";
  std::string save_prefix;
};

std::atomic<bool> stop_requested{false};
extern "C" void request_stop(int) { stop_requested = true; }

// PREFIX defaults to SCENE's directory and stem; a JSON scene's saved copy must sit beside it,
// where its relative paths resolve.
std::string save_prefix_for(const ViewCommand& cmd) {
  namespace fs = std::filesystem;
  const fs::path scene(cmd.render.scene);
  const std::string prefix =
      cmd.save_prefix.empty() ? (scene.parent_path() / (scene.stem().string() + "-view")).string() : cmd.save_prefix;
  const fs::path dir = fs::path(prefix).parent_path();
  check_output_location(prefix + "-1.json", "--save-prefix");
  std::error_code ec;
  if (!is_gltf_path(cmd.render.scene) &&
      !fs::equivalent(dir.empty() ? "." : dir, scene.parent_path().empty() ? "." : scene.parent_path(), ec))
    throw InputError("--save-prefix " + prefix + ": a JSON scene's saved copy goes in the scene's own directory (" +
                     (scene.parent_path().empty() ? std::string(".") : scene.parent_path().string()) +
                     "), where the files it names resolve");
  return prefix;
}

int run_view(const ViewCommand& cmd) {
  const RenderCommand& r = cmd.render;
  if (r.device != "cpu" && r.device != "cuda") throw InputError("--device " + r.device + ": expected cpu or cuda");
  if (!r.samples.empty()) throw InputError("--samples: the viewer renders every sample in turn; use tracer render");
  if (cmd.port < 0 || cmd.port > 65535)
    throw InputError("--port " + std::to_string(cmd.port) + ": expected 0 to 65535");
  if (r.device == "cuda") cuda_device_description();  // fail before loading when there is no GPU
  ViewOptions options;
  options.scene_path = r.scene;
  options.scene_text = read_text_file(r.scene, "scene file", is_gltf_path(r.scene) ? kMaxGltfFileBytes : UINT64_MAX);
  options.overrides = scene_overrides(r);
  options.threads = r.threads;
  options.cuda = r.device == "cuda";
  options.save_prefix = save_prefix_for(cmd);
  ViewSession session(options);
  ViewServer server(session, cmd.bind, cmd.port);
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  session.start();
  std::thread serving([&] { server.serve(); });
  std::printf("%s\n", server.url().c_str());
  std::fflush(stdout);
  std::fprintf(stderr,
               "tracer view: open the URL above (from another machine: ssh -L %d:127.0.0.1:%d HOST, then the same "
               "URL); Ctrl-C stops\n",
               server.port(), server.port());
  if (cmd.bind == "0.0.0.0" || cmd.bind == "::")
    std::fprintf(stderr, "tracer view: listening on every address: put this machine's name in the URL in place of %s\n",
                 cmd.bind.c_str());
  while (!stop_requested) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server.stop();
  serving.join();
  session.stop();
  return 0;
}

}  // namespace

const RegisterCommand kViewCommand(
    {"", "view", "serve a page on 127.0.0.1 that shows the scene as it renders, with a movable camera",
     [](CLI::App& app) {
       auto cmd = std::make_shared<ViewCommand>();
       add_scene_options(app, cmd->render);
       add_threads_option(app, cmd->render.threads);
       app.add_option("--device", cmd->render.device, "cpu or cuda");
       app.add_option("--port", cmd->port, "the port (default 0: a free one, printed with the URL)");
       app.add_option("--bind", cmd->bind,
                      "the address to listen on (default 127.0.0.1: this machine only; reach it from another "
                      "through an SSH tunnel)");
       app.add_option("--save-prefix", cmd->save_prefix,
                      "where the page's save writes PREFIX-N.json, .exr and .png (default: beside the scene, "
                      "SCENE-view)");
       return [cmd] { return run_view(*cmd); };
     }});

}  // namespace tracer
