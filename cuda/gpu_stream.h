// The stream schedule on the GPU (docs/path.md, "The stream schedule"): render/stream_schedule.h's
// loop with a CUDA grid per stage (a kernel per StreamStage, so each holds only its stage's
// code and registers), the work queue split into the next queues by one kernel with an
// atomic per warp and queue, and the batch's samples added to the film in pixel-sample
// order by one thread per pixel. Shared by
// `--device cuda` and the runner, for whole renders (gpu_film.cu) and adaptive passes
// (gpu_adaptive.cu). CUDA header: included by .cu files only.
#pragma once
#include <optional>

#include "device_buffer.h"
#include "ray_order_gpu.h"
#include "render/stream_schedule.h"
#include "render/stream_states.h"

namespace tracer {

// The closest-hit (StreamStage::Closest) or shadow stage (StreamStage::Shadow) with the
// scene's trace variant over the states queue[0, size) of `states` (device memory), on the
// default stream: what `tracer bench rays --device cuda` times (trace_rays_cuda.cu).
void launch_trace_stage(const SceneView& device_view, StreamStage stage, const StreamStates& states,
                        const uint32_t* queue, size_t size);

class GpuStream {
 public:
  // Device bytes of the states and queues for at most `total` samples in flight at a time.
  static size_t device_bytes(const SceneView& view, uint64_t total);

  // Ray states and queues on the device for min(stream_width, total) samples; `order` is the
  // host view's stream_order_frame (render/stream_order_frame.h).
  GpuStream(const SceneView& device_view, uint64_t total, std::optional<RayOrderFrame> order);

  // `target` holds device pointers; ray counts are added to counters[0..2] (camera,
  // secondary, shadow) on the device. Returns the seconds between the first and last
  // kernel (CUDA events), the host's compaction waits included.
  double render(const StreamTarget& target, unsigned long long* counters, StreamStats& stats);

 private:
  SceneView scene_;
  size_t width_;
  std::vector<DeviceBuffer<unsigned char>> blocks_;
  StreamStates states_{};
  DeviceBuffer<uint32_t> queues_[4];
  DeviceBuffer<uint32_t> split_sizes_;
  std::optional<RayOrderFrame> order_;
  std::optional<GpuRaySorter> sorter_;  // with an order
};

}  // namespace tracer
