// Adaptive sampling on the GPU: render/adaptive_schedule.h's loop with CUDA grids for its
// passes and for the decision (kernel/integrator/adaptive.h's pixel_unconverged and
// neighbourhood_unconverged, the functions the CPU schedulers call), the sums staying on the
// device between checkpoints. Shared by `--device cuda` and the runner. Plain C++ header.
#pragma once
#include <string>

#include "gpu_run.h"
#include "kernel/integrator/ray_counts.h"
#include "render/adaptive_film.h"
#include "render/stream_schedule.h"
#include "scene/scene_arrays.h"

namespace tracer {

struct GpuAdaptiveFilm {
  AdaptiveFilm film;
  RayCounts rays{};
  StreamStats stream;  // the stream schedule's queues and memory (zero for the megakernel)
  GpuRun run;          // the transfers of the running lists and keep flags count as downloads
};

// bvh's 8-wide tree goes to the device where `view` counts one (device_scene.h).
// DeviceUnavailable (no device; too little free memory, naming `label`) or
// std::runtime_error naming the failing CUDA call.
GpuAdaptiveFilm render_adaptive_on_gpu(const SceneArrays& arrays, const SceneView& view, const std::string& label);

}  // namespace tracer
