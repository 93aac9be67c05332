#include <chrono>
#include <cstdio>

#include "cuda_device.h"
#include "cuda_event.h"
#include "device_scene.h"
#include "gpu_film.h"
#include "gpu_stream.h"
#include "render/stream_order_frame.h"
#include "kernel/integrator/render_pixel.h"

namespace tracer {
namespace {

enum Counter { kCamera, kSecondary, kShadow, kNonfinite, kOverflow, kCounterCount };

// 16x16 blocks; each thread loops over its pixel's samples in index order, with the code of
// the integrator kKind alone (render_pixel_as).
template <IntegratorKind kKind, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
__device__ void render_pixels(const SceneView& scene, SampleRange range, FilmSum* film, unsigned long long* counters) {
  const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
  if (x >= scene.settings.width || y >= scene.settings.height) return;
  RayCounts counts = {0, 0, 0};
  const FilmSum sum = render_pixel_as<kKind, kFeatures>(scene, x, y, range.begin, range.end, counts);
  film[static_cast<size_t>(y) * scene.settings.width + x] = sum;
  // Integer sums: the totals do not depend on the order threads add them in.
  atomicAdd(&counters[kCamera], static_cast<unsigned long long>(counts.camera));
  atomicAdd(&counters[kSecondary], static_cast<unsigned long long>(counts.secondary));
  atomicAdd(&counters[kShadow], static_cast<unsigned long long>(counts.shadow));
  if (sum.nonfinite) atomicAdd(&counters[kNonfinite], static_cast<unsigned long long>(sum.nonfinite));
  if (sum.overflow) atomicAdd(&counters[kOverflow], static_cast<unsigned long long>(sum.overflow));
}

// The megakernel, one per integrator and named for it, so that none holds another's registers
// and stack (docs/cuda.md, "Resource budgets"), each without the code of a feature a scene
// lacks where it costs the most (kernel/base/features.h): Whitted without and with cut-outs;
// the path tracer without mirror images and cut-outs, with cut-outs alone, and with both.
__global__ void whitted_render_kernel(const SceneView scene, SampleRange range, FilmSum* film,
                                      unsigned long long* counters) {
  render_pixels<IntegratorKind::Whitted, kKernelWithoutAlpha>(scene, range, film, counters);
}

__global__ void whitted_alpha_render_kernel(const SceneView scene, SampleRange range, FilmSum* film,
                                            unsigned long long* counters) {
  render_pixels<IntegratorKind::Whitted>(scene, range, film, counters);
}

__global__ void path_render_kernel(const SceneView scene, SampleRange range, FilmSum* film,
                                   unsigned long long* counters) {
  render_pixels<IntegratorKind::Path, kKernelWithoutMirrorImagesOrAlpha>(scene, range, film, counters);
}

__global__ void path_alpha_render_kernel(const SceneView scene, SampleRange range, FilmSum* film,
                                         unsigned long long* counters) {
  render_pixels<IntegratorKind::Path, kKernelWithoutMirrorImages>(scene, range, film, counters);
}

__global__ void path_mirror_images_render_kernel(const SceneView scene, SampleRange range, FilmSum* film,
                                                 unsigned long long* counters) {
  render_pixels<IntegratorKind::Path>(scene, range, film, counters);
}

// normals, albedo and depth
__global__ void view_render_kernel(const SceneView scene, SampleRange range, FilmSum* film,
                                   unsigned long long* counters) {
  render_pixels<IntegratorKind::Normals>(scene, range, film, counters);
}

using RenderKernel = void (*)(const SceneView, SampleRange, FilmSum*, unsigned long long*);

RenderKernel render_kernel_for(const SceneView& view) {
  const bool alpha = (view.features & kFeatureAlpha) != 0u;
  switch (view.settings.integrator) {
    case IntegratorKind::Whitted: return alpha ? whitted_alpha_render_kernel : whitted_render_kernel;
    case IntegratorKind::Path:
      return view.mirror_count > 0 ? path_mirror_images_render_kernel
             : alpha               ? path_alpha_render_kernel
                                   : path_render_kernel;
    default: return view_render_kernel;
  }
}

constexpr int kRenderThreads = 256;  // 16x16

std::string describe_render_kernel(const char* name, RenderKernel kernel, const cudaDeviceProp& prop) {
  cudaFuncAttributes attr{};
  TRACER_CUDA_CHECK(cudaFuncGetAttributes(&attr, kernel));
  int blocks = 0;
  TRACER_CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&blocks, kernel, kRenderThreads, 0));
  const int by_registers = attr.numRegs > 0 ? prop.regsPerMultiprocessor / (attr.numRegs * kRenderThreads) : blocks;
  const int by_threads = prop.maxThreadsPerMultiProcessor / kRenderThreads;
  const char* limit = by_registers <= by_threads && by_registers <= prop.maxBlocksPerMultiProcessor ? "registers"
                      : by_threads <= prop.maxBlocksPerMultiProcessor                               ? "threads per SM"
                                                                                                    : "blocks per SM";
  char text[512];
  std::snprintf(text, sizeof text,
                "%s: %d registers, %zu bytes of local memory (stack and spills) per thread; 16x16 blocks: "
                "%d resident per SM of %d threads = %.0f %% occupancy, limited by %s (%d SMs, %d registers per SM)",
                name, attr.numRegs, static_cast<size_t>(attr.localSizeBytes), blocks, prop.maxThreadsPerMultiProcessor,
                100.0 * blocks * kRenderThreads / prop.maxThreadsPerMultiProcessor, limit, prop.multiProcessorCount,
                prop.regsPerMultiprocessor);
  return text;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

std::string describe_render_kernel() {
  const cudaDeviceProp prop = select_cuda_device();
  return describe_render_kernel("whitted_render_kernel", whitted_render_kernel, prop) + "\n" +
         describe_render_kernel("whitted_alpha_render_kernel", whitted_alpha_render_kernel, prop) + "\n" +
         describe_render_kernel("path_render_kernel", path_render_kernel, prop) + "\n" +
         describe_render_kernel("path_alpha_render_kernel", path_alpha_render_kernel, prop) + "\n" +
         describe_render_kernel("path_mirror_images_render_kernel", path_mirror_images_render_kernel, prop) + "\n" +
         describe_render_kernel("view_render_kernel", view_render_kernel, prop);
}

GpuFilm render_film_on_gpu(const SceneArrays& arrays, const SceneView& view, SampleRange range,
                           const std::string& label) {
  const cudaDeviceProp prop = select_cuda_device();
  GpuFilm r;
  r.run.device = describe_cuda_device(prop);
  const RenderSettings& rs = view.settings;
  const size_t pixels = static_cast<size_t>(rs.width) * rs.height;
  const bool stream = rs.schedule == Schedule::Stream;
  const uint64_t samples = static_cast<uint64_t>(pixels) * (range.end - range.begin);
  r.run.device_bytes = DeviceScene::bytes(arrays, device_bvh_of(view)) + pixels * sizeof(FilmSum) +
                       kCounterCount * sizeof(unsigned long long) +
                       (stream ? GpuStream::device_bytes(view, samples) : 0);
  require_free_device_memory(r.run.device_bytes,
                             stream ? label + " (--stream-width " + std::to_string(rs.stream_width) + ")" : label,
                             r.run.device);

  auto t = std::chrono::steady_clock::now();
  const DeviceScene device_scene(arrays, view, device_bvh_of(view), label);
  DeviceBuffer<FilmSum> film(pixels);
  DeviceBuffer<unsigned long long> counters(kCounterCount);
  counters.zero();
  if (stream) {
    film.zero();
    GpuStream states(device_scene.view(), samples, stream_order_frame(view));
    TRACER_CUDA_CHECK(cudaDeviceSynchronize());
    r.run.upload_seconds = seconds_since(t);
    const StreamTarget target = {nullptr, pixels, range.begin, range.end, film.get(), nullptr, nullptr};
    r.run.kernel_seconds = states.render(target, counters.get(), r.stream);
  } else {
    TRACER_CUDA_CHECK(cudaDeviceSynchronize());
    r.run.upload_seconds = seconds_since(t);
    const CudaEvent start, stop;
    const dim3 block(16, 16), grid((rs.width + 15) / 16, (rs.height + 15) / 16);
    TRACER_CUDA_CHECK(cudaEventRecord(start.event));
    render_kernel_for(view)<<<grid, block>>>(device_scene.view(), range, film.get(), counters.get());
    TRACER_CUDA_CHECK(cudaGetLastError());
    TRACER_CUDA_CHECK(cudaEventRecord(stop.event));
    r.run.kernel_seconds = seconds_between(start, stop);
  }

  t = std::chrono::steady_clock::now();
  r.film.width = rs.width;
  r.film.height = rs.height;
  r.film.range = range;
  r.film.pixels = film.download();
  const std::vector<unsigned long long> c = counters.download();
  r.run.download_seconds = seconds_since(t);
  r.rays = {c[kCamera], c[kSecondary], c[kShadow]};
  r.nonfinite = c[kNonfinite];
  r.overflow = c[kOverflow];
  if (stream) {  // the stream's kernels count no samples; the film's sums do
    for (const FilmSum& sum : r.film.pixels) {
      r.nonfinite += sum.nonfinite;
      r.overflow += sum.overflow;
    }
  }
  return r;
}

}  // namespace tracer
