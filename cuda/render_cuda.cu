// The CUDA scheduler: one thread per pixel, 16x16 blocks, each thread looping over the
// pixel's samples in index order through kernel/render_pixel.h, the function the CPU runs.
// With the strict flags of DESIGN.md rule 1 the pixels equal the CPU's bit for bit.
#include <chrono>

#include "cuda_device.h"
#include "device_scene.h"
#include "kernel/render_pixel.h"
#include "render_cuda.h"

namespace tracer {
namespace {

enum Counter { kCamera, kSecondary, kShadow, kNonfinite, kOverflow, kCounterCount };

__global__ void render_kernel(const SceneView scene, SampleRange range, FilmSum* film, unsigned long long* counters) {
  const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= scene.settings.width || y >= scene.settings.height) return;
  RayCounts counts = {0, 0, 0};
  const FilmSum sum = render_pixel(scene, x, y, range.begin, range.end, counts);
  film[static_cast<size_t>(y) * scene.settings.width + x] = sum;
  // Integer sums: the totals do not depend on the order threads add them in.
  atomicAdd(&counters[kCamera], static_cast<unsigned long long>(counts.camera));
  atomicAdd(&counters[kSecondary], static_cast<unsigned long long>(counts.secondary));
  atomicAdd(&counters[kShadow], static_cast<unsigned long long>(counts.shadow));
  if (sum.nonfinite) atomicAdd(&counters[kNonfinite], static_cast<unsigned long long>(sum.nonfinite));
  if (sum.overflow) atomicAdd(&counters[kOverflow], static_cast<unsigned long long>(sum.overflow));
}

// A CUDA event that is destroyed even when a later call throws.
struct CudaEvent {
  cudaEvent_t event = nullptr;
  CudaEvent() { TRACER_CUDA_CHECK(cudaEventCreate(&event)); }
  ~CudaEvent() { cudaEventDestroy(event); }
  CudaEvent(const CudaEvent&) = delete;
  CudaEvent& operator=(const CudaEvent&) = delete;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

std::string cuda_device_description() { return describe_cuda_device(select_cuda_device()); }

FilmBuffer render_cuda_film(const Scene& scene, SampleRange range, RenderStats& stats, CudaRunInfo& info) {
  const cudaDeviceProp prop = select_cuda_device();
  info.device = describe_cuda_device(prop);
  const RenderSettings& rs = scene.settings;
  const size_t pixels = static_cast<size_t>(rs.width) * rs.height;
  info.device_bytes = scene_array_bytes(scene) + pixels * sizeof(FilmSum) + kCounterCount * sizeof(unsigned long long);
  size_t free_bytes = 0, total_bytes = 0;
  TRACER_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  if (info.device_bytes > free_bytes)
    throw DeviceUnavailable(scene.file + ": the scene needs " + std::to_string(info.device_bytes >> 20) +
                            " MiB of device memory; " + info.device + " has " + std::to_string(free_bytes >> 20) +
                            " MiB free");

  auto t = std::chrono::steady_clock::now();
  const DeviceScene device_scene(scene, scene.view());
  DeviceBuffer<FilmSum> film(pixels);
  DeviceBuffer<unsigned long long> counters(kCounterCount);
  counters.zero();
  TRACER_CUDA_CHECK(cudaDeviceSynchronize());
  info.upload_seconds = seconds_since(t);

  const CudaEvent start, stop;
  const dim3 block(16, 16), grid((rs.width + 15) / 16, (rs.height + 15) / 16);
  TRACER_CUDA_CHECK(cudaEventRecord(start.event));
  render_kernel<<<grid, block>>>(device_scene.view(), range, film.get(), counters.get());
  TRACER_CUDA_CHECK(cudaGetLastError());
  TRACER_CUDA_CHECK(cudaEventRecord(stop.event));
  TRACER_CUDA_CHECK(cudaEventSynchronize(stop.event));
  float kernel_ms = 0.0f;
  TRACER_CUDA_CHECK(cudaEventElapsedTime(&kernel_ms, start.event, stop.event));
  info.kernel_seconds = kernel_ms / 1000.0;

  t = std::chrono::steady_clock::now();
  FilmBuffer result;
  result.width = rs.width;
  result.height = rs.height;
  result.range = range;
  result.pixels = film.download();
  const std::vector<unsigned long long> c = counters.download();
  info.download_seconds = seconds_since(t);
  stats.rays = {c[kCamera], c[kSecondary], c[kShadow]};
  stats.nonfinite_samples = c[kNonfinite];
  stats.overflow_samples = c[kOverflow];
  return result;
}

Image render_cuda(const Scene& scene, RenderStats& stats, CudaRunInfo& info) {
  const uint32_t spp = scene.settings.spp;
  return resolve_film(render_cuda_film(scene, {0, spp}, stats, info), spp);
}

}  // namespace tracer
