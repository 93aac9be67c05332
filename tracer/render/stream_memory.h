// A stream render allocates the ray states of all its samples in flight at once. More than half
// of the memory this process may use (io/memory_limit.h: the machine's, or its memory cgroup's
// limit when lower) is refused before the allocation, naming --stream-width, since Linux would
// lend the memory and kill the process when it is touched. Header-only: the GPU runner's CPU
// stream checks it too.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "io/memory_limit.h"
#include "render/stream_schedule.h"
#include "render/stream_states.h"

namespace tracer {

// "FLAG W: B bytes of ray states for N samples in flight WHY; give a smaller width", the one
// wording of every refusal of a stream width (bench schedule's flag is --widths).
inline std::string stream_width_refusal(const SceneView& view, uint64_t total_samples, const std::string& why,
                                        const std::string& flag = "--stream-width") {
  const size_t width = stream_width_for(view.settings, total_samples);
  return flag + " " + std::to_string(view.settings.stream_width) + ": " +
         std::to_string(static_cast<uint64_t>(stream_bytes_per_state(view)) * width) + " bytes of ray states for " +
         std::to_string(width) + " samples in flight " + why + "; give a smaller width";
}

inline std::optional<std::string> stream_memory_refusal(const SceneView& view, uint64_t total_samples,
                                                        const std::string& flag = "--stream-width") {
  static const MemoryLimit limit = memory_limit();  // read once: an adaptive render asks every pass
  const uint64_t bytes =
      static_cast<uint64_t>(stream_bytes_per_state(view)) * stream_width_for(view.settings, total_samples);
  if (limit.bytes == 0 || bytes <= limit.bytes / 2) return std::nullopt;
  return stream_width_refusal(view, total_samples,
                              "exceed half of " + limit.source + ", " + std::to_string(limit.bytes) + " bytes", flag);
}

}  // namespace tracer
