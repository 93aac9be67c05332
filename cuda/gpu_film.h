// Renders samples of every pixel on the GPU from a scene's arrays and view scalars: one
// thread per pixel runs kernel/integrator/render_pixel.h, the function the CPU schedulers run
// (render.schedule stream: the stream schedule, gpu_stream.h). Shared
// by the tracer's `--device cuda` (render_cuda.cu) and the self-contained runner
// (cuda/runner/), so both launch exactly the same kernel. Plain C++ header: no CUDA types.
#pragma once
#include <string>

#include "gpu_run.h"
#include "kernel/integrator/ray_counts.h"
#include "render/film_buffer.h"
#include "render/stream_schedule.h"
#include "scene/scene_arrays.h"

namespace tracer {

struct GpuFilm {
  FilmBuffer film;
  RayCounts rays{};
  uint64_t nonfinite = 0, overflow = 0;
  StreamStats stream;  // the stream schedule's queues and memory (zero for the megakernel)
  GpuRun run;
};

// The render kernels on this device, one line for each integrator's: registers and local
// memory per thread (ptxas's figures, as the driver reports them), resident 16x16 blocks per
// multiprocessor, the occupancy they give and what limits it. DeviceUnavailable without a
// usable GPU.
std::string describe_render_kernel();

// The same for the stream schedule's four stage kernels (gpu_stream.cu), a line each.
std::string describe_stream_kernels();

// bvh's 8-wide tree goes to the device where `view` counts one (device_scene.h).
// DeviceUnavailable (no device; too little free memory, naming `label`) or
// std::runtime_error naming the failing CUDA call.
GpuFilm render_film_on_gpu(const SceneArrays& arrays, const SceneView& view, SampleRange range,
                           const std::string& label);

}  // namespace tracer
