#include <chrono>

#include "cuda_device.h"
#include "cuda_event.h"
#include "device_scene.h"
#include "gpu_adaptive.h"
#include "gpu_stream.h"
#include "kernel/integrator/adaptive.h"
#include "kernel/integrator/render_pixel.h"
#include "render/adaptive_schedule.h"
#include "render/stream_order_frame.h"

namespace tracer {
namespace {

constexpr uint32_t kBlock = 128;

enum Counter { kCamera, kSecondary, kShadow, kCounterCount };

uint32_t blocks_for(size_t n) { return static_cast<uint32_t>((n + kBlock - 1) / kBlock); }

// One thread per running pixel: samples [begin, end) into its even and odd sums, with the code
// of the integrator kKind alone (render_pixel_halves_as).
template <IntegratorKind kKind, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
__device__ void adaptive_pass(const SceneView& scene, const uint32_t* running, size_t count, uint32_t begin,
                              uint32_t end, FilmSum* even, FilmSum* odd, unsigned long long* counters) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const uint32_t p = running[i];
  RayCounts counts = {0, 0, 0};
  render_pixel_halves_as<kKind, kFeatures>(scene, p % scene.settings.width, p / scene.settings.width, begin, end,
                                           even[p], odd[p], counts);
  atomicAdd(&counters[kCamera], static_cast<unsigned long long>(counts.camera));
  atomicAdd(&counters[kSecondary], static_cast<unsigned long long>(counts.secondary));
  atomicAdd(&counters[kShadow], static_cast<unsigned long long>(counts.shadow));
}

// A pass kernel per integrator and feature set, named for it (as gpu_film.cu's render kernels).
__global__ void whitted_adaptive_pass_kernel(const SceneView scene, const uint32_t* running, size_t count,
                                             uint32_t begin, uint32_t end, FilmSum* even, FilmSum* odd,
                                             unsigned long long* counters) {
  adaptive_pass<IntegratorKind::Whitted, kKernelWithoutAlpha>(scene, running, count, begin, end, even, odd, counters);
}

__global__ void whitted_alpha_adaptive_pass_kernel(const SceneView scene, const uint32_t* running, size_t count,
                                                   uint32_t begin, uint32_t end, FilmSum* even, FilmSum* odd,
                                                   unsigned long long* counters) {
  adaptive_pass<IntegratorKind::Whitted>(scene, running, count, begin, end, even, odd, counters);
}

__global__ void path_adaptive_pass_kernel(const SceneView scene, const uint32_t* running, size_t count, uint32_t begin,
                                          uint32_t end, FilmSum* even, FilmSum* odd, unsigned long long* counters) {
  adaptive_pass<IntegratorKind::Path, kKernelWithoutMirrorImagesOrAlpha>(scene, running, count, begin, end, even, odd,
                                                                         counters);
}

__global__ void path_alpha_adaptive_pass_kernel(const SceneView scene, const uint32_t* running, size_t count,
                                                uint32_t begin, uint32_t end, FilmSum* even, FilmSum* odd,
                                                unsigned long long* counters) {
  adaptive_pass<IntegratorKind::Path, kKernelWithoutMirrorImages>(scene, running, count, begin, end, even, odd,
                                                                  counters);
}

__global__ void path_mirror_images_adaptive_pass_kernel(const SceneView scene, const uint32_t* running, size_t count,
                                                        uint32_t begin, uint32_t end, FilmSum* even, FilmSum* odd,
                                                        unsigned long long* counters) {
  adaptive_pass<IntegratorKind::Path>(scene, running, count, begin, end, even, odd, counters);
}

// normals, albedo and depth
__global__ void view_adaptive_pass_kernel(const SceneView scene, const uint32_t* running, size_t count, uint32_t begin,
                                          uint32_t end, FilmSum* even, FilmSum* odd, unsigned long long* counters) {
  adaptive_pass<IntegratorKind::Normals>(scene, running, count, begin, end, even, odd, counters);
}

using AdaptivePassKernel = void (*)(const SceneView, const uint32_t*, size_t, uint32_t, uint32_t, FilmSum*, FilmSum*,
                                    unsigned long long*);

AdaptivePassKernel adaptive_pass_kernel_for(const SceneView& view) {
  const bool alpha = (view.features & kFeatureAlpha) != 0u;
  switch (view.settings.integrator) {
    case IntegratorKind::Whitted: return alpha ? whitted_alpha_adaptive_pass_kernel : whitted_adaptive_pass_kernel;
    case IntegratorKind::Path:
      return view.mirror_count > 0 ? path_mirror_images_adaptive_pass_kernel
             : alpha               ? path_alpha_adaptive_pass_kernel
                                   : path_adaptive_pass_kernel;
    default: return view_adaptive_pass_kernel;
  }
}

// The decision's first step over the running pixels (the map's other pixels are 0).
__global__ void mark_unconverged_kernel(const uint32_t* running, size_t count, const FilmSum* even, const FilmSum* odd,
                                        uint32_t samples, float threshold, uint8_t* unconverged) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < count) unconverged[running[i]] = pixel_unconverged(even[running[i]], odd[running[i]], samples, threshold);
}

// The second step: each running pixel keeps sampling while it or a neighbour is unconverged.
__global__ void keep_kernel(const uint32_t* running, size_t count, const uint8_t* unconverged, uint32_t width,
                            uint32_t height, uint8_t* keep) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < count)
    keep[i] = neighbourhood_unconverged(unconverged, width, height, running[i] % width, running[i] / width) ? 1u : 0u;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

struct GpuBackend {
  SceneView scene;  // pointing at device arrays
  DeviceBuffer<FilmSum> even, odd;
  DeviceBuffer<uint32_t> running;
  DeviceBuffer<uint8_t> unconverged, keep_flags;
  DeviceBuffer<unsigned long long> counters;
  GpuStream stream;  // sized for none with the megakernel schedule
  StreamStats stream_stats;
  double kernel_seconds = 0, transfer_seconds = 0;

  GpuBackend(const SceneView& device_view, size_t pixels, std::optional<RayOrderFrame> order)
      : scene(device_view),
        even(pixels),
        odd(pixels),
        running(pixels),
        unconverged(pixels),
        keep_flags(pixels),
        counters(kCounterCount),
        stream(device_view, stream_samples(device_view.settings, pixels), order) {
    even.zero(), odd.zero(), counters.zero();
  }

  // A pass renders at most every pixel's spp samples.
  static uint64_t stream_samples(const RenderSettings& rs, size_t pixels) {
    return rs.schedule == Schedule::Stream ? static_cast<uint64_t>(pixels) * rs.spp : 0;
  }

  void upload_running(const std::vector<uint32_t>& list) {
    const auto t = std::chrono::steady_clock::now();
    TRACER_CUDA_CHECK(cudaMemcpy(running.get(), list.data(), list.size() * sizeof(uint32_t), cudaMemcpyHostToDevice));
    transfer_seconds += seconds_since(t);
  }

  void render(AdaptiveFilm&, const std::vector<uint32_t>& list, uint32_t begin, uint32_t end, uint64_t) {
    upload_running(list);
    if (scene.settings.schedule == Schedule::Stream) {
      const StreamTarget target = {running.get(), list.size(), begin, end, nullptr, even.get(), odd.get()};
      kernel_seconds += stream.render(target, counters.get(), stream_stats);
      return;
    }
    const CudaEvent start, stop;
    TRACER_CUDA_CHECK(cudaEventRecord(start.event));
    adaptive_pass_kernel_for(scene)<<<blocks_for(list.size()), kBlock>>>(scene, running.get(), list.size(), begin, end,
                                                                         even.get(), odd.get(), counters.get());
    TRACER_CUDA_CHECK(cudaGetLastError());
    TRACER_CUDA_CHECK(cudaEventRecord(stop.event));
    kernel_seconds += seconds_between(start, stop);
  }

  void read_sums(AdaptiveFilm& film) {
    const auto t = std::chrono::steady_clock::now();
    film.even = even.download();
    film.odd = odd.download();
    transfer_seconds += seconds_since(t);
  }

  std::vector<uint8_t> keep(AdaptiveFilm& film, const std::vector<uint32_t>& list, uint32_t checkpoint,
                            float threshold) {
    unconverged.zero();
    mark_unconverged_kernel<<<blocks_for(list.size()), kBlock>>>(running.get(), list.size(), even.get(), odd.get(),
                                                                 checkpoint, threshold, unconverged.get());
    TRACER_CUDA_CHECK(cudaGetLastError());
    keep_kernel<<<blocks_for(list.size()), kBlock>>>(running.get(), list.size(), unconverged.get(), film.width,
                                                     film.height, keep_flags.get());
    TRACER_CUDA_CHECK(cudaGetLastError());
    std::vector<uint8_t> flags(list.size());
    TRACER_CUDA_CHECK(cudaMemcpy(flags.data(), keep_flags.get(), flags.size(), cudaMemcpyDeviceToHost));
    return flags;
  }
};

}  // namespace

GpuAdaptiveFilm render_adaptive_on_gpu(const SceneArrays& arrays, const SceneView& view, const std::string& label) {
  const cudaDeviceProp prop = select_cuda_device();
  GpuAdaptiveFilm r;
  r.run.device = describe_cuda_device(prop);
  const RenderSettings& rs = view.settings;
  const size_t pixels = static_cast<size_t>(rs.width) * rs.height;
  const bool stream = rs.schedule == Schedule::Stream;
  r.run.device_bytes = DeviceScene::bytes(arrays, device_bvh_of(view)) +
                       pixels * (2 * sizeof(FilmSum) + sizeof(uint32_t) + 2) +
                       kCounterCount * sizeof(unsigned long long) +
                       GpuStream::device_bytes(view, GpuBackend::stream_samples(rs, pixels));
  require_free_device_memory(r.run.device_bytes,
                             stream ? label + " (--stream-width " + std::to_string(rs.stream_width) + ")" : label,
                             r.run.device);

  auto t = std::chrono::steady_clock::now();
  const DeviceScene device_scene(arrays, view, device_bvh_of(view), label);
  GpuBackend backend(device_scene.view(), pixels, stream_order_frame(view));
  TRACER_CUDA_CHECK(cudaDeviceSynchronize());
  r.run.upload_seconds = seconds_since(t);

  r.film = schedule_adaptive(rs, backend);
  const std::vector<unsigned long long> c = backend.counters.download();
  r.rays = {c[kCamera], c[kSecondary], c[kShadow]};
  r.stream = backend.stream_stats;
  r.run.kernel_seconds = backend.kernel_seconds;
  r.run.download_seconds = backend.transfer_seconds;
  return r;
}

}  // namespace tracer
