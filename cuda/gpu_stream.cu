#include <cstdio>
#include <stdexcept>
#include <string>

#include "cuda_device.h"
#include "cuda_event.h"
#include "gpu_stream.h"
#include "kernel/accel/trace_variants.h"
#include "render/stream_schedule.h"

namespace tracer {
namespace {

constexpr uint32_t kBlock = 128;

uint32_t blocks_for(size_t n) { return static_cast<uint32_t>((n + kBlock - 1) / kBlock); }

// Items [first, first + count) of the target, pixel-major, as states 0..count-1; the work
// queue in order.
__global__ void begin_batch_kernel(StreamTarget target, uint64_t first, size_t count, StreamStates st, uint32_t* work) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= count) return;
  stream_begin_item(target, st, first, i);
  work[i] = static_cast<uint32_t>(i);
}

// Stage kStage over a queue, its ray counts added to the counters; the shade stage with the
// code of the integrator kKind alone (stream_shade_as).
template <StreamStage kStage, IntegratorKind kKind = IntegratorKind::Path, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
__device__ void run_stage(const SceneView& scene, const StreamStates& st, const uint32_t* queue, size_t size,
                          unsigned long long* counters) {
  const size_t q = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (q >= size) return;
  RayCounts counts = {0, 0, 0};
  if constexpr (kStage == StreamStage::Shade)
    stream_shade_as<kKind, kFeatures>(scene, st, queue[q], counts);
  else
    stream_stage(scene, kStage, st, queue[q], counts);
  // Integer sums: the totals do not depend on the order threads add them in.
  if (counts.camera) atomicAdd(&counters[0], static_cast<unsigned long long>(counts.camera));
  if (counts.secondary) atomicAdd(&counters[1], static_cast<unsigned long long>(counts.secondary));
  if (counts.shadow) atomicAdd(&counters[2], static_cast<unsigned long long>(counts.shadow));
}

// Each stage is a kernel of its own, and the shade stage one per integrator, each named for
// what it does: each holds only its own code, and ptxas' report and profilers name it
// (docs/cuda.md, "Resource budgets").
#define TRACER_STAGE_KERNEL(name, ...)                                                             \
  __global__ void name(const SceneView scene, StreamStates st, const uint32_t* queue, size_t size, \
                       unsigned long long* counters) {                                             \
    run_stage<__VA_ARGS__>(scene, st, queue, size, counters);                                      \
  }
TRACER_STAGE_KERNEL(generate_stage_kernel, StreamStage::Generate)
// the path tracer without and with mirror images' code, as gpu_film.cu's
TRACER_STAGE_KERNEL(path_shade_stage_kernel, StreamStage::Shade, IntegratorKind::Path, kKernelWithoutMirrorImages)
TRACER_STAGE_KERNEL(path_mirror_images_shade_stage_kernel, StreamStage::Shade, IntegratorKind::Path)
TRACER_STAGE_KERNEL(whitted_shade_stage_kernel, StreamStage::Shade, IntegratorKind::Whitted)
TRACER_STAGE_KERNEL(view_shade_stage_kernel, StreamStage::Shade, IntegratorKind::Normals)  // normals, albedo, depth
#undef TRACER_STAGE_KERNEL

// The closest-hit and shadow stages with the trace code kCode (kernel/accel/trace_code.h).
// They count no rays.
template <uint32_t kCode, bool kShadow>
__device__ void run_trace_stage(const SceneView& scene, const StreamStates& st, const uint32_t* queue, size_t size) {
  const size_t q = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (q >= size) return;
  if constexpr (kShadow)
    stream_shadow<kCode>(scene, st, queue[q]);
  else
    stream_closest<kCode>(scene, st, queue[q]);
}

// A trace stage kernel held to `blocks` blocks of kBlock threads per SM (65,536 / (blocks *
// 128) registers); what ptxas reports for each is in docs/cuda.md, "Resource budgets".
#define TRACER_TRACE_KERNEL(kernel, code, shadow, blocks)                                                       \
  __global__ void __launch_bounds__(kBlock, blocks)                                                             \
      kernel(const SceneView scene, StreamStates st, const uint32_t* queue, size_t size, unsigned long long*) { \
    run_trace_stage<code, shadow>(scene, st, queue, size);                                                      \
  }
// The full code, for scenes no variant holds: 72 registers, 7 blocks.
TRACER_TRACE_KERNEL(closest_hit_stage_kernel, kTraceAll, false, 7)
TRACER_TRACE_KERNEL(shadow_any_hit_stage_kernel, kTraceAll, true, 7)
// A pair per trace variant (kernel/accel/trace_variants.h), only its structure's traversal and
// its shapes' tests: 64 registers, 8 blocks.
#define TRACER_TRACE_VARIANT_KERNELS(name, code)                   \
  TRACER_TRACE_KERNEL(closest_hit_##name##_kernel, code, false, 8) \
  TRACER_TRACE_KERNEL(shadow_any_hit_##name##_kernel, code, true, 8)
TRACER_TRACE_VARIANTS(TRACER_TRACE_VARIANT_KERNELS)
#undef TRACER_TRACE_VARIANT_KERNELS
#undef TRACER_TRACE_KERNEL

using StageKernel = void (*)(const SceneView, StreamStates, const uint32_t*, size_t, unsigned long long*);

#define TRACER_CLOSEST_KERNEL(name, code) closest_hit_##name##_kernel,
#define TRACER_SHADOW_KERNEL(name, code) shadow_any_hit_##name##_kernel,
constexpr StageKernel kClosestKernels[] = {TRACER_TRACE_VARIANTS(TRACER_CLOSEST_KERNEL)};
constexpr StageKernel kShadowKernels[] = {TRACER_TRACE_VARIANTS(TRACER_SHADOW_KERNEL)};
#undef TRACER_CLOSEST_KERNEL
#undef TRACER_SHADOW_KERNEL

StageKernel stage_kernel_for(StreamStage stage, const SceneView& scene) {
  const int variant =
      trace_variant_of(scene.features, scene.settings, scene.wide_node_count != 0, scene.bvh_pair_count != 0);
  switch (stage) {
    case StreamStage::Generate: return generate_stage_kernel;
    case StreamStage::Closest: return variant < 0 ? closest_hit_stage_kernel : kClosestKernels[variant];
    case StreamStage::Shadow: return variant < 0 ? shadow_any_hit_stage_kernel : kShadowKernels[variant];
    case StreamStage::Shade: break;
  }
  switch (scene.settings.integrator) {
    case IntegratorKind::Path:
      return scene.mirror_count > 0 ? path_mirror_images_shade_stage_kernel : path_shade_stage_kernel;
    case IntegratorKind::Whitted: return whitted_shade_stage_kernel;
    default: return view_shade_stage_kernel;
  }
}

// The batch's radiance into the film, one thread per pixel, its samples in order.
__global__ void end_batch_kernel(StreamTarget target, uint64_t first, size_t count, uint64_t first_pixel,
                                 uint64_t pixels, StreamStates st) {
  const uint64_t k = static_cast<uint64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k < pixels) stream_end_pixel(target, st, first, count, first_pixel + k);
}

// An index of `queue` for each lane whose `pred` holds, one atomic per warp (every lane of the
// warp calls it).
__device__ void warp_append(bool pred, uint32_t value, uint32_t* queue, uint32_t* size) {
  const unsigned lane = threadIdx.x % 32u, mask = __ballot_sync(0xffffffffu, pred);
  if (mask == 0u) return;
  const unsigned leader = static_cast<unsigned>(__ffs(mask)) - 1u;
  uint32_t base = 0;
  if (lane == leader) base = atomicAdd(size, static_cast<uint32_t>(__popc(mask)));
  base = __shfl_sync(0xffffffffu, base, leader);
  if (pred) queue[base + static_cast<uint32_t>(__popc(mask & ((1u << lane) - 1u)))] = value;
}

// The work queue split by next[] bits into the trace, shadow and resume queues, in the order
// the warps arrive: a queue's order changes no sample (stream_schedule.h).
__global__ void split_kernel(const uint32_t* work, size_t size, const uint8_t* next, uint32_t* trace, uint32_t* shadow,
                             uint32_t* resume, uint32_t* sizes) {
  const size_t k = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const uint32_t i = k < size ? work[k] : 0u;
  const uint8_t bits = k < size ? next[i] : 0u;
  warp_append((bits & kStreamTrace) != 0u, i, trace, &sizes[0]);
  warp_append((bits & kStreamShadow) != 0u, i, shadow, &sizes[1]);
  warp_append((bits & kStreamResume) != 0u, i, resume, &sizes[2]);
}

// Device memory for the state arrays (cudaMalloc aligns every block to 256 bytes).
struct DeviceArrays {
  std::vector<DeviceBuffer<unsigned char>>& blocks;
  template <class T>
  T* operator()(T*, size_t count) {
    blocks.emplace_back(count * sizeof(T));
    return reinterpret_cast<T*>(blocks.back().get());
  }
};

// The CUDA backend of schedule_stream.
struct CudaStream {
  const SceneView& scene;
  const StreamTarget& target;
  const StreamStates& states;
  DeviceBuffer<uint32_t>* queues;
  unsigned long long* counters;
  uint32_t* split_sizes;  // 3 on the device
  GpuRaySorter* sorter;   // null without render.stream_order sorted

  uint32_t* queue(StreamQueue q) { return queues[static_cast<uint32_t>(q)].get(); }

  void begin_batch(uint64_t first, size_t count) {
    begin_batch_kernel<<<blocks_for(count), kBlock>>>(target, first, count, states, queue(StreamQueue::Work));
    TRACER_CUDA_CHECK(cudaGetLastError());
  }

  void run(StreamStage stage, StreamQueue q, size_t size) {
    if (size == 0) return;
    const uint32_t grid = blocks_for(size);
    stage_kernel_for(stage, scene)<<<grid, kBlock>>>(scene, states, queue(q), size, counters);
    TRACER_CUDA_CHECK(cudaGetLastError());
  }

  size_t append(StreamQueue to, size_t to_size, StreamQueue from, size_t from_size) {
    if (from_size > 0)
      TRACER_CUDA_CHECK(
          cudaMemcpyAsync(queue(to) + to_size, queue(from), from_size * sizeof(uint32_t), cudaMemcpyDeviceToDevice));
    return to_size + from_size;
  }

  StreamSplit split(size_t work) {
    if (work == 0) return {0, 0, 0};
    TRACER_CUDA_CHECK(cudaMemsetAsync(split_sizes, 0, 3 * sizeof(uint32_t)));
    split_kernel<<<blocks_for(work), kBlock>>>(queue(StreamQueue::Work), work, states.next, queue(StreamQueue::Trace),
                                               queue(StreamQueue::Shadow), resume_queue(), split_sizes);
    TRACER_CUDA_CHECK(cudaGetLastError());
    uint32_t sizes[3];
    TRACER_CUDA_CHECK(cudaMemcpy(sizes, split_sizes, sizeof sizes, cudaMemcpyDeviceToHost));
    return {sizes[0], sizes[1], sizes[2]};
  }

  // Only a Whitted vertex resumes; other integrators have no resume queue and set no such bit.
  uint32_t* resume_queue() { return queues[static_cast<uint32_t>(StreamQueue::Resume)].get(); }

  // Sorted into the sorter's buffer, then copied back: the queue keeps its place among the four.
  void sort(StreamQueue q, size_t size, const RayOrderFrame& frame) {
    if (size == 0) return;
    const bool shadow = q == StreamQueue::Shadow;
    const uint32_t* sorted = sorter->sort(frame, shadow ? states.shadow_origin : states.origin,
                                          shadow ? states.shadow_dir : states.dir, queue(q), size);
    TRACER_CUDA_CHECK(cudaMemcpyAsync(queue(q), sorted, size * sizeof(uint32_t), cudaMemcpyDeviceToDevice));
  }

  void swap(StreamQueue a, StreamQueue b) {
    std::swap(queues[static_cast<uint32_t>(a)], queues[static_cast<uint32_t>(b)]);
  }

  void end_batch(uint64_t first, size_t count) {
    const uint64_t samples = target.end - target.begin;
    const uint64_t first_pixel = first / samples, pixels = (first + count - 1) / samples - first_pixel + 1;
    end_batch_kernel<<<blocks_for(pixels), kBlock>>>(target, first, count, first_pixel, pixels, states);
    TRACER_CUDA_CHECK(cudaGetLastError());
  }
};

template <class Kernel>
std::string describe_kernel(const char* name, Kernel kernel, const cudaDeviceProp& prop) {
  cudaFuncAttributes attr{};
  TRACER_CUDA_CHECK(cudaFuncGetAttributes(&attr, kernel));
  int blocks = 0;
  TRACER_CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&blocks, kernel, kBlock, 0));
  char text[256];
  std::snprintf(text, sizeof text,
                "%s: %d registers, %zu bytes of local memory per thread; %u-thread blocks: %.0f %% occupancy", name,
                attr.numRegs, static_cast<size_t>(attr.localSizeBytes), kBlock,
                100.0 * blocks * kBlock / prop.maxThreadsPerMultiProcessor);
  return text;
}

}  // namespace

void launch_trace_stage(const SceneView& device_view, StreamStage stage, const StreamStates& states,
                        const uint32_t* queue, size_t size) {
  if (stage != StreamStage::Closest && stage != StreamStage::Shadow)
    throw std::logic_error("launch_trace_stage: not a trace stage");
  if (size == 0) return;
  stage_kernel_for(stage, device_view)<<<blocks_for(size), kBlock>>>(device_view, states, queue, size, nullptr);
  TRACER_CUDA_CHECK(cudaGetLastError());
}

std::string describe_stream_kernels() {
  const cudaDeviceProp prop = select_cuda_device();
  std::string variants;
  for (int v = 0; v < kTraceVariantCount; ++v) {
    const std::string name = kTraceVariants[v].name;
    variants += "\n" + describe_kernel(("closest_hit_" + name + "_kernel").c_str(), kClosestKernels[v], prop) + "\n" +
                describe_kernel(("shadow_any_hit_" + name + "_kernel").c_str(), kShadowKernels[v], prop);
  }
  return describe_kernel("generate_stage_kernel", generate_stage_kernel, prop) + "\n" +
         describe_kernel("closest_hit_stage_kernel", closest_hit_stage_kernel, prop) + "\n" +
         describe_kernel("path_shade_stage_kernel", path_shade_stage_kernel, prop) + "\n" +
         describe_kernel("path_mirror_images_shade_stage_kernel", path_mirror_images_shade_stage_kernel, prop) + "\n" +
         describe_kernel("whitted_shade_stage_kernel", whitted_shade_stage_kernel, prop) + "\n" +
         describe_kernel("view_shade_stage_kernel", view_shade_stage_kernel, prop) + "\n" +
         describe_kernel("shadow_any_hit_stage_kernel", shadow_any_hit_stage_kernel, prop) + variants;
}

size_t GpuStream::device_bytes(const SceneView& view, uint64_t total) {
  return stream_bytes_per_state(view) * stream_width_for(view.settings, total);
}

GpuStream::GpuStream(const SceneView& device_view, uint64_t total, std::optional<RayOrderFrame> order)
    : scene_(device_view), width_(stream_width_for(device_view.settings, total)), order_(order) {
  if (width_ == 0) return;
  states_ = allocate_stream_states(scene_, width_, DeviceArrays{blocks_});
  for (uint32_t q = 0; q < stream_queue_count(scene_.settings); ++q) queues_[q] = DeviceBuffer<uint32_t>(width_);
  split_sizes_ = DeviceBuffer<uint32_t>(3);
  if (order_) sorter_.emplace(width_);
}

double GpuStream::render(const StreamTarget& target, unsigned long long* counters, StreamStats& stats) {
  const uint64_t total = static_cast<uint64_t>(target.count) * (target.end - target.begin);
  stats.bytes_per_state = stream_bytes_per_state(scene_);
  stats.state_bytes = stats.bytes_per_state * width_;
  if (total == 0) return 0.0;
  CudaStream backend{scene_, target, states_, queues_, counters, split_sizes_.get(), sorter_ ? &*sorter_ : nullptr};
  const CudaEvent start, stop;
  TRACER_CUDA_CHECK(cudaEventRecord(start.event));
  schedule_stream(total, width_, backend, stats, order_);
  TRACER_CUDA_CHECK(cudaEventRecord(stop.event));
  return seconds_between(start, stop);
}

}  // namespace tracer
