// The render behind `tracer view`: one thread owns the scene and refines its image sample
// range after sample range into a fixed-point film, exactly as `tracer render` sums them, so
// the frame at N samples is the image `render` draws at N spp. While the camera moves it draws
// one sample at a quarter of the size instead. Other threads (the HTTP server's) only post
// requests and read the latest frame, under one mutex.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "options/render_options.h"
#include "render/film_buffer.h"
#include "render/render_cpu.h"
#include "scene/scene.h"

namespace tracer {

struct ViewFrame {
  uint64_t id = 0;                         // grows with every frame drawn
  std::shared_ptr<const std::string> png;  // the frame, encoded; shared, so a state read copies no image
  uint32_t width = 0, height = 0;
  uint32_t spp = 0, target_spp = 0;
  bool preview = false;  // drawn while the camera moves: a quarter of the size, one sample
  double pass_seconds = 0.0, rays_per_second = 0.0;
  std::string integrator;
  CameraSpec camera{};
  std::string error;        // the last request the render could not apply
  float scene_size = 0.0f;  // the diagonal of the bounded shapes' box: the page's unit of movement
};

struct ViewOptions {
  std::string scene_path, scene_text;
  RenderOverrides overrides;  // the command line's, as `render` takes them
  int threads = 0;
  bool cuda = false;
  std::string save_prefix;  // saves go to PREFIX-N.{json,exr,png}, N the first number free
};

class ViewSession {
 public:
  explicit ViewSession(ViewOptions options);  // loads the scene: InputError as `render` gives
  ~ViewSession();
  void start();
  void stop();

  // Requests from any thread. A camera checked by the scene file's rules (InputError).
  void move_camera(const CameraSpec& camera, bool moving);
  // A render option by its command-line name and text ("integrator", "spp"), checked as the
  // command line's are (InputError naming it); the film restarts with it.
  void set_option(const std::string& name, const std::string& text);
  ViewFrame frame() const;
  // Writes the image at rest and a scene file with its camera; returns the paths written.
  // Waits for the render thread; InputError when it cannot (moving, nothing rendered yet).
  std::vector<std::string> save();

  CameraSpec camera() const;

 private:
  struct Request {
    CameraSpec camera{};
    bool moving = false;
    RenderOverrides overrides;
    uint64_t generation = 0;  // any change restarts the film
    uint64_t reload = 0;      // an option changed: the scene is loaded again with the overrides
  };
  void run();
  void publish(const FilmBuffer& film, uint32_t spp, bool preview, double seconds, const RenderStats& stats);
  FilmBuffer render_range(SampleRange range, RenderStats& stats);
  std::vector<std::string> write_saved(const FilmBuffer& film, uint32_t spp) const;

  ViewOptions options_;
  Scene scene_;                // the render thread's alone once started
  CameraSpec scene_camera_{};  // the scene file's camera, whose lens a moved camera keeps
  uint32_t full_width_ = 0, full_height_ = 0;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  Request request_;
  ViewFrame frame_;
  bool stopping_ = false;
  std::vector<std::promise<std::vector<std::string>>> saves_;
  std::thread thread_;
};

}  // namespace tracer
