#include "cuda_device.h"
#include "device_buffer.h"
#include "device_scene.h"
#include "gpu_stream.h"
#include "render/stream_order_frame.h"
#include "parity_gpu.h"

namespace tracer::parity {
namespace {

constexpr uint32_t kBlock = 256;

uint32_t blocks_for(size_t n) { return static_cast<uint32_t>((n + kBlock - 1) / kBlock); }

void finish_launch() {
  TRACER_CUDA_CHECK(cudaGetLastError());
  TRACER_CUDA_CHECK(cudaDeviceSynchronize());
}

__global__ void math_kernel(MathFunction f, const float* a, const float* b, float* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_math(f, a[i], b[i]);
}

__global__ void philox_kernel(const PhiloxQuery* q, Philox4* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_philox(q[i]);
}

__global__ void shape_kernel(const ShapeQuery* q, ShapeAnswer* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_shape(q[i]);
}

__global__ void bsdf_kernel(const BsdfQuery* q, BsdfAnswer* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_bsdf_case(q[i]);
}

__global__ void adaptive_kernel(const AdaptiveQuery* q, AdaptiveAnswer* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_adaptive(q[i]);
}

__global__ void trace_kernel(const SceneView scene, const Ray* rays, TraceAnswer* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_trace(scene, rays[i]);
}

__global__ void sample_kernel(const SceneView scene, SampleAnswer* out, size_t n) {
  const size_t i = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) out[i] = eval_sample(scene, static_cast<uint32_t>(i));
}

}  // namespace

std::string gpu_device() { return describe_cuda_device(select_cuda_device()); }

std::vector<float> gpu_math(MathFunction f, const std::vector<float>& a, const std::vector<float>& b) {
  select_cuda_device();
  const DeviceBuffer<float> da(a), db(b);
  DeviceBuffer<float> out(a.size());
  math_kernel<<<blocks_for(a.size()), kBlock>>>(f, da.get(), db.get(), out.get(), a.size());
  finish_launch();
  return out.download();
}

std::vector<Philox4> gpu_philox(const std::vector<PhiloxQuery>& queries) {
  select_cuda_device();
  const DeviceBuffer<PhiloxQuery> q(queries);
  DeviceBuffer<Philox4> out(queries.size());
  philox_kernel<<<blocks_for(queries.size()), kBlock>>>(q.get(), out.get(), queries.size());
  finish_launch();
  return out.download();
}

std::vector<ShapeAnswer> gpu_shapes(const std::vector<ShapeQuery>& queries) {
  select_cuda_device();
  const DeviceBuffer<ShapeQuery> q(queries);
  DeviceBuffer<ShapeAnswer> out(queries.size());
  shape_kernel<<<blocks_for(queries.size()), kBlock>>>(q.get(), out.get(), queries.size());
  finish_launch();
  return out.download();
}

std::vector<BsdfAnswer> gpu_bsdfs(const std::vector<BsdfQuery>& queries) {
  select_cuda_device();
  const DeviceBuffer<BsdfQuery> q(queries);
  DeviceBuffer<BsdfAnswer> out(queries.size());
  bsdf_kernel<<<blocks_for(queries.size()), kBlock>>>(q.get(), out.get(), queries.size());
  finish_launch();
  return out.download();
}

std::vector<AdaptiveAnswer> gpu_adaptive(const std::vector<AdaptiveQuery>& queries) {
  select_cuda_device();
  const DeviceBuffer<AdaptiveQuery> q(queries);
  DeviceBuffer<AdaptiveAnswer> out(queries.size());
  adaptive_kernel<<<blocks_for(queries.size()), kBlock>>>(q.get(), out.get(), queries.size());
  finish_launch();
  return out.download();
}

std::vector<TraceAnswer> gpu_trace(const SceneArrays& arrays, const SceneView& view, const std::vector<Ray>& rays) {
  select_cuda_device();
  const DeviceScene device_scene(arrays, view);
  const DeviceBuffer<Ray> r(rays);
  DeviceBuffer<TraceAnswer> out(rays.size());
  trace_kernel<<<blocks_for(rays.size()), kBlock>>>(device_scene.view(), r.get(), out.get(), rays.size());
  finish_launch();
  return out.download();
}

std::vector<SampleAnswer> gpu_samples(const SceneArrays& arrays, const SceneView& view) {
  select_cuda_device();
  const DeviceScene device_scene(arrays, view);
  const size_t n = static_cast<size_t>(view.settings.width) * view.settings.height;
  DeviceBuffer<SampleAnswer> out(n);
  sample_kernel<<<blocks_for(n), kBlock>>>(device_scene.view(), out.get(), n);
  finish_launch();
  return out.download();
}

std::vector<Vec3> gpu_stream_samples(const SceneArrays& arrays, const SceneView& view) {
  select_cuda_device();
  const DeviceScene device_scene(arrays, view);
  const uint64_t items = static_cast<uint64_t>(view.settings.width) * view.settings.height * view.settings.spp;
  DeviceBuffer<Vec3> out(items);
  DeviceBuffer<unsigned long long> counters(3);
  counters.zero();
  GpuStream stream(device_scene.view(), items, stream_order_frame(view));
  StreamTarget target = {
      nullptr, static_cast<size_t>(view.settings.width) * view.settings.height, 0u, view.settings.spp, nullptr, nullptr,
      nullptr};
  target.samples = out.get();
  StreamStats stats;
  stream.render(target, counters.get(), stats);
  finish_launch();
  return out.download();
}

}  // namespace tracer::parity
