// The limits on one render's size and work, applied by every reader of a description of a
// render: the scene loader (with the command line), scene bundles, partial files and the
// Slurm job record (docs/scene-format.md, "What bad input gets"). Header-only: the GPU
// runner applies them too.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "kernel/integrator/ray_counts.h"

namespace tracer {

constexpr uint32_t kMaxResolution = 16384;    // film.width and film.height at most
constexpr uint64_t kMaxSamples = 1ull << 36;  // spp x width x height at most: hours on one machine

struct WorkLimitViolation {
  std::string key;     // "width", "height", "spp" or "max_depth", as the scene's render and film name them
  std::string reason;  // names the limit
};

inline std::optional<WorkLimitViolation> work_limit_violation(uint64_t width, uint64_t height, uint64_t spp,
                                                              uint64_t max_depth) {
  for (const auto& [size, name] : {std::pair{width, "width"}, std::pair{height, "height"}})
    if (size < 1 || size > kMaxResolution)
      return WorkLimitViolation{name, "must be in [1, " + std::to_string(kMaxResolution) +
                                          "] (the film's limit), got " + std::to_string(size)};
  if (spp < 1) return WorkLimitViolation{"spp", "spp must be at least 1"};
  if (spp > kMaxSamples / (width * height))
    return WorkLimitViolation{"spp", std::to_string(spp) + " spp x " + std::to_string(width) + " x " +
                                         std::to_string(height) +
                                         " pixels is more than 2^36 samples (the work limit: hours on one machine); "
                                         "lower spp or the film size"};
  if (max_depth > kMaxDepth)
    return WorkLimitViolation{"max_depth", "must be at most " + std::to_string(kMaxDepth) + " (the depth limit), got " +
                                               std::to_string(max_depth)};
  return std::nullopt;
}

}  // namespace tracer
