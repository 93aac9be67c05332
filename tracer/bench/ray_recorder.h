// The rays a CPU render casts, recorded once so that `tracer bench path` can replay them
// through closest-hit and any-hit alone and compare the rates (traversal against the whole
// path tracer). Rays are stored as 7 floats: origin, direction, tmax.
#pragma once
#include <cstdint>
#include <vector>

namespace tracer {

struct SceneView;

struct RecordedRays {
  std::vector<float> closest, any;  // 7 floats per ray
};

// Renders samples [sample_begin, sample_end) of every pixel on one thread with a copy of the
// kernel that records every trace_closest and trace_any (kernel/accel/trace.h's hook).
RecordedRays record_rays(const SceneView& view, uint32_t sample_begin, uint32_t sample_end);

}  // namespace tracer
