// What every integrator counts and bounds: rays cast by kind, and the deepest path.
#pragma once
#include <cstdint>

namespace tracer {

constexpr uint32_t kMaxDepth = 64;  // the loader rejects a larger max_depth

struct RayCounts {
  uint64_t camera, secondary, shadow;
};

}  // namespace tracer
