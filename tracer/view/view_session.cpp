#include "view/view_session.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "accel/bounds.h"
#include "image/image_io.h"
#include "io/input_error.h"
#include "io/output_batch.h"
#include "options/enum_names.h"
#include "render/partial_file.h"
#include "render/render_adaptive.h"
#include "render/render_cuda.h"
#include "scene/gltf_file.h"
#include "scene/scene_loader.h"
#include "view/view_scene_file.h"

namespace tracer {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPassSeconds = 0.25;    // a refining pass takes about this long, then a frame is shown
constexpr uint32_t kPreviewDivisor = 4;  // a moving camera is drawn at a quarter of the width and height

// The camera a moved look-at keeps: the scene's lens, focused at the new target unless the
// scene focused elsewhere.
CameraSpec with_lens_of(const CameraSpec& scene_camera, CameraSpec moved) {
  moved.aperture = scene_camera.aperture;
  const bool focused_on_target = scene_camera.focus_distance == length(scene_camera.to - scene_camera.from);
  moved.focus_distance = focused_on_target ? length(moved.to - moved.from) : scene_camera.focus_distance;
  return moved;
}

}  // namespace

ViewSession::ViewSession(ViewOptions options) : options_(std::move(options)) {
  scene_ = load_scene_text(options_.scene_text, options_.scene_path, options_.overrides);
  if (adaptive_render(scene_.settings))
    throw InputError(options_.scene_path +
                     ": noise_threshold, target_error: the viewer refines every pixel alike; set them off (0) "
                     "or use tracer render");
  full_width_ = scene_.settings.width, full_height_ = scene_.settings.height;
  scene_camera_ = scene_.camera_spec;
  request_.camera = scene_.camera_spec;
  request_.overrides = options_.overrides;
  frame_.target_spp = scene_.settings.spp;
  frame_.camera = scene_.camera_spec;
  frame_.integrator = enum_name(scene_.settings.integrator);
  const Bounds bounds = bounds_of_primitives(scene_.primitives.data(), scene_.primitives.size());
  frame_.scene_size = bounds.lo.x <= bounds.hi.x ? length(bounds.hi - bounds.lo) : 0.0f;
}

ViewSession::~ViewSession() { stop(); }

void ViewSession::start() {
  thread_ = std::thread([this] { run(); });
}

void ViewSession::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void ViewSession::move_camera(const CameraSpec& camera, bool moving) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    request_.camera = with_lens_of(scene_camera_, camera);
    request_.moving = moving;
    ++request_.generation;
  }
  wake_.notify_all();
}

void ViewSession::set_option(const std::string& name, const std::string& text) {
  if (name != "integrator" && name != "spp")
    throw InputError("option " + name + ": the viewer sets integrator and spp");
  {
    std::lock_guard<std::mutex> lock(mutex_);
    RenderOverrides next = request_.overrides;
    parse_option_text(name, text, "request ", next);
    request_.overrides = next;
    ++request_.generation;
    ++request_.reload;
  }
  wake_.notify_all();
}

ViewFrame ViewSession::frame() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return frame_;
}

CameraSpec ViewSession::camera() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return request_.camera;
}

std::vector<std::string> ViewSession::save() {
  std::future<std::vector<std::string>> done;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) throw InputError("the viewer is stopping");
    saves_.emplace_back();
    done = saves_.back().get_future();
  }
  wake_.notify_all();
  return done.get();  // the render thread answers between passes
}

FilmBuffer ViewSession::render_range(SampleRange range, RenderStats& stats) {
  if (options_.cuda) {
    CudaRunInfo info;
    return render_cuda_film(scene_, range, stats, info);
  }
  return render_cpu_film(scene_, range, options_.threads, stats);
}

void ViewSession::publish(const FilmBuffer& film, uint32_t spp, bool preview, double seconds,
                          const RenderStats& stats) {
  auto png = std::make_shared<const std::string>(encode_image(resolve_film(film, spp), "frame.png"));
  const uint64_t rays = stats.rays.camera + stats.rays.secondary + stats.rays.shadow;
  std::lock_guard<std::mutex> lock(mutex_);
  frame_.id += 1;
  frame_.png = std::move(png);
  frame_.width = film.width, frame_.height = film.height;
  frame_.spp = spp, frame_.target_spp = scene_.settings.spp;
  frame_.preview = preview;
  frame_.pass_seconds = seconds;
  frame_.rays_per_second = seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0;
  frame_.integrator = enum_name(scene_.settings.integrator);
  frame_.camera = scene_.camera_spec;
}

std::vector<std::string> ViewSession::write_saved(const FilmBuffer& film, uint32_t spp) const {
  if (spp == 0) throw InputError("nothing rendered at rest yet: wait for the first full-size frame");
  const SavedNames names = free_save_names(options_.save_prefix);
  OutputBatch outputs;
  const Image image = resolve_film(film, spp);
  add_image(outputs, image, names.exr);
  add_image(outputs, image, names.png);
  std::vector<std::string> written{names.exr, names.png};
  if (!is_gltf_path(options_.scene_path)) {
    outputs.add(names.json, scene_file_with_view(options_.scene_text, scene_.settings, scene_.camera_spec, spp));
  } else {
    outputs.add(names.json, camera_block_text(scene_.camera_spec) + "\n");
  }
  written.push_back(names.json);
  outputs.commit();
  return written;
}

void ViewSession::run() {
  FilmBuffer film;
  uint32_t done = 0;
  uint64_t generation = UINT64_MAX, reload = 0;
  uint64_t placed_generation = UINT64_MAX;  // the camera and film size the scene holds
  bool placed_preview = false;
  bool preview_shown = false;
  bool stopped = false;             // this camera's image refines no further: a pass failed
  double seconds_per_sample = 0.0;  // of the last refining pass
  for (;;) {
    Request request;
    std::vector<std::promise<std::vector<std::string>>> saves;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] {
        return stopping_ || !saves_.empty() || request_.generation != generation ||
               (!request_.moving && !stopped && done < scene_.settings.spp) || (request_.moving && !preview_shown);
      });
      if (stopping_) {
        for (auto& s : saves_) s.set_exception(std::make_exception_ptr(InputError("the viewer is stopping")));
        return;
      }
      request = request_;
      saves.swap(saves_);
    }
    for (auto& s : saves) {
      try {
        if (request.moving || request.generation != generation) throw InputError("the camera is moving: save at rest");
        s.set_value(write_saved(film, done));
      } catch (...) {
        s.set_exception(std::current_exception());
      }
    }
    try {
      if (request.reload != reload) {
        reload = request.reload;
        Scene next = load_scene_text(options_.scene_text, options_.scene_path, request.overrides);
        scene_ = std::move(next);
        full_width_ = scene_.settings.width, full_height_ = scene_.settings.height;
        std::lock_guard<std::mutex> lock(mutex_);
        frame_.error.clear();
      }
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      frame_.error = e.what();
    }
    if (request.generation != generation) {
      generation = request.generation;
      done = 0, preview_shown = false, stopped = false;
    }
    const bool preview = request.moving;
    if (preview && preview_shown) continue;
    if (generation != placed_generation || preview != placed_preview) {  // the offset scale walks every shape
      scene_.settings.width = preview ? std::max(1u, full_width_ / kPreviewDivisor) : full_width_;
      scene_.settings.height = preview ? std::max(1u, full_height_ / kPreviewDivisor) : full_height_;
      place_camera(scene_, request.camera);
      placed_generation = generation, placed_preview = preview;
    }
    if (!preview && (stopped || done >= scene_.settings.spp)) continue;
    // One sample first, then as many as fill a pass of about kPassSeconds.
    uint32_t batch = 1;
    if (!preview && done > 0 && seconds_per_sample > 0.0)
      batch = static_cast<uint32_t>(std::clamp(kPassSeconds / seconds_per_sample, 1.0, 1e6));
    const SampleRange range =
        preview ? SampleRange{0, 1} : SampleRange{done, std::min(scene_.settings.spp, done + batch)};
    RenderStats stats;
    const auto start = Clock::now();
    FilmBuffer part;
    try {
      part = render_range(range, stats);
    } catch (const std::exception& e) {  // the page shows why; the next request tries again
      std::lock_guard<std::mutex> lock(mutex_);
      frame_.error = e.what();
      stopped = preview_shown = true;
      continue;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (preview) {
      preview_shown = true;
      publish(part, 1, true, seconds, stats);
      continue;
    }
    seconds_per_sample = seconds / (range.end - range.begin);
    if (done == 0) {
      film = std::move(part);
    } else if (const size_t pixel = add_film_sums(film, part); pixel < film.pixels.size()) {
      std::lock_guard<std::mutex> lock(mutex_);
      frame_.error = "pixel " + std::to_string(pixel) + " would pass the film's range with samples [" +
                     std::to_string(range.begin) + ", " + std::to_string(range.end) + "): the image stops at " +
                     std::to_string(done) + " samples";
      stopped = true;
      continue;
    }
    done = range.end;
    publish(film, done, false, seconds, stats);
  }
}

}  // namespace tracer
