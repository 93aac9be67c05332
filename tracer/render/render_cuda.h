// The CUDA renderer's host interface (cuda/render_cuda.cu): one GPU thread per pixel runs
// kernel/integrator/render_pixel.h, the function the CPU's tile loop runs, over the scene's flat arrays
// copied to plain device buffers. Built whenever CMake finds nvcc; a build without it links
// render_cuda_absent.cpp instead, whose functions raise DeviceUnavailable.
#pragma once
#include <string>

#include "image/image.h"
#include "render/adaptive_film.h"
#include "render/render_cpu.h"
#include "scene/scene.h"

namespace tracer {

struct CudaRunInfo {
  std::string device;       // "NVIDIA H100 80GB HBM3 (sm_90, 79.1 GiB)"
  size_t device_bytes = 0;  // scene arrays + image + counters on the device
  double upload_seconds = 0, kernel_seconds = 0, download_seconds = 0;
};

// The first CUDA device, described; DeviceUnavailable when there is none usable.
std::string cuda_device_description();

// Samples `range` of every pixel on the GPU; DeviceUnavailable (no device, too little
// memory) or std::runtime_error naming the failing CUDA call.
FilmBuffer render_cuda_film(const Scene& scene, SampleRange range, RenderStats& stats, CudaRunInfo& info);

// An adaptive render (render.noise_threshold, render.target_error) on the GPU: the film of
// the CPU's render_cpu_adaptive, bit for bit.
AdaptiveFilm render_cuda_adaptive(const Scene& scene, RenderStats& stats, CudaRunInfo& info);

// All samples, resolved to an image; adaptively when the scene asks.
Image render_cuda(const Scene& scene, RenderStats& stats, CudaRunInfo& info);

}  // namespace tracer
