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

// The refusal's text names `flag` (bench schedule's is --widths).
inline std::optional<std::string> stream_memory_refusal(const RenderSettings& rs, uint64_t total_samples,
                                                        const std::string& flag = "--stream-width") {
  const MemoryLimit limit = memory_limit();
  const size_t width = stream_width_for(rs, total_samples);
  const uint64_t bytes = static_cast<uint64_t>(stream_bytes_per_state(rs)) * width;
  if (limit.bytes == 0 || bytes <= limit.bytes / 2) return std::nullopt;
  return flag + " " + std::to_string(rs.stream_width) + ": " + std::to_string(bytes) +
         " bytes of ray states for " + std::to_string(width) + " samples in flight exceed half of " + limit.source +
         ", " + std::to_string(limit.bytes) + " bytes; give a smaller width";
}

}  // namespace tracer
