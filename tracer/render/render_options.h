// The options that decide a render's pixels besides the scene's contents: what a golden's
// manifest entry records and what a partial file carries so that `tracer merge` only adds
// up parts of one render. Each may be unset (the scene file decides).
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace tracer {

struct RenderOptions {
  std::optional<std::string> integrator, sampler, accel;
  std::optional<uint32_t> spp, width, height, max_depth;
  std::optional<uint64_t> seed;
  std::optional<bool> nee;             // path integrator only; recorded when resolved
  std::optional<uint32_t> rr_depth;    // path integrator only; recorded when resolved
  std::optional<bool> sky_sampling;    // path under a cube-map sky only; recorded when resolved
  std::optional<std::string> triangle_test;  // recorded when resolved to moller-trumbore

  bool complete() const;                     // the eight options every golden records are set
  RenderOverrides overrides() const;         // as command-line overrides of a scene
  nlohmann::ordered_json to_json() const;    // the set options, in a fixed order
};

// Every option as the loaded scene resolved it (scene file plus overrides).
RenderOptions resolved_options(const Scene& scene);

}  // namespace tracer
