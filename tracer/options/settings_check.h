// What every render's settings hold, however they were made: the scene loader builds them so
// (scene/settings_reader.cpp, whose messages name the scene's keys), and a scene bundle's reader
// (bundle/scene_bundle.cpp: `tracer-gpu`, `tracer bundle`'s readers) checks them so, since a
// bundle's checksum proves only that its bytes are the ones written. Header-only: the GPU
// runner applies it too.
#pragma once
#include <limits>
#include <optional>
#include <string>

#include "kernel/scene/render_settings.h"
#include "options/work_limits.h"

namespace tracer {

// A threshold (noise_threshold, target_error) is 0 (off) or in [kThresholdMin, kThresholdMax].
// The renderer holds it as a float, where a decimal such as 1e-50 is 0 ("off", a uniform
// render) and 1e-40 is subnormal: a float's smallest normal number is the least value that
// means what its text says.
constexpr double kThresholdMin = std::numeric_limits<float>::min();
constexpr double kThresholdMax = 1e6;

// The first setting that is not one a render can have, and why; nullopt when all are.
inline std::optional<WorkLimitViolation> settings_violation(const RenderSettings& rs) {
  if (const auto v = work_limit_violation(rs.width, rs.height, rs.spp, rs.max_depth)) return v;
  // An enum's value beyond its last enumerator, or a number beyond its limit.
  const auto beyond = [](const char* key, auto value, auto last) -> std::optional<WorkLimitViolation> {
    if (static_cast<uint32_t>(value) <= static_cast<uint32_t>(last)) return std::nullopt;
    return WorkLimitViolation{key, "no such value: " + std::to_string(static_cast<uint32_t>(value))};
  };
  for (const auto& v : {beyond("integrator", rs.integrator, IntegratorKind::Path),
                        beyond("sampler", rs.sampler, SamplerKind::Sobol), beyond("accel", rs.accel, AccelKind::Lbvh),
                        beyond("nee", rs.nee, Switch::On), beyond("sky_sampling", rs.sky_sampling, Switch::On),
                        beyond("light_sampling", rs.light_sampling, LightSampling::SolidAngle),
                        beyond("mirror_images", rs.mirror_images, Switch::On),
                        beyond("triangle_test", rs.triangle_test, TriangleTest::MollerTrumbore),
                        beyond("effects", rs.effects, kEffectAll), beyond("schedule", rs.schedule, Schedule::Stream),
                        beyond("stream_order", rs.stream_order, StreamOrder::Sorted),
                        beyond("grid_resolution", rs.grid_resolution, 1024u)})
    if (v) return v;
  // grid_n is derived: the least n with n^2 >= spp (the grid and stratified samplers divide by it).
  if (rs.grid_n < 1 || static_cast<uint64_t>(rs.grid_n) * rs.grid_n < rs.spp ||
      static_cast<uint64_t>(rs.grid_n - 1) * (rs.grid_n - 1) >= rs.spp)
    return WorkLimitViolation{
        "grid_n", "is " + std::to_string(rs.grid_n) + ", not the sampler grid of " + std::to_string(rs.spp) + " spp"};
  if (rs.stream_width < 1 || rs.stream_width > kMaxStreamWidth)
    return WorkLimitViolation{"stream_width", "expected 1 to " + std::to_string(kMaxStreamWidth) +
                                                  " samples in flight, got " + std::to_string(rs.stream_width)};
  const auto admissible = [](float v) { return v == 0.0f || (v >= kThresholdMin && v <= kThresholdMax); };
  if (!admissible(rs.noise_threshold) || !admissible(rs.target_error))
    return WorkLimitViolation{"noise_threshold", "noise_threshold " + std::to_string(rs.noise_threshold) +
                                                     ", target_error " + std::to_string(rs.target_error) +
                                                     ": expected 0 (off) or from 1.2e-38 to 1e6"};
  // An adaptive render estimates a pixel's error from two halves of its samples.
  if (adaptive_render(rs) && rs.spp < 2)
    return WorkLimitViolation{"spp",
                              "adaptive sampling estimates the error from two halves of a pixel's samples: "
                              "at least 2, got " +
                                  std::to_string(rs.spp)};
  if (adaptive_render(rs) && rs.min_spp < 2)
    return WorkLimitViolation{"min_spp", "adaptive sampling estimates the error from two halves: at least 2, got " +
                                             std::to_string(rs.min_spp)};
  return std::nullopt;
}

}  // namespace tracer
