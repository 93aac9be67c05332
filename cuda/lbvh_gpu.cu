#include <thrust/execution_policy.h>
#include <thrust/sort.h>

#include <chrono>

#include "cuda_device.h"
#include "cuda_event.h"
#include "device_buffer.h"
#include "lbvh_gpu.h"

namespace tracer {
namespace {

constexpr uint32_t kBlock = 256;

uint32_t blocks_for(size_t n) { return static_cast<uint32_t>((n + kBlock - 1) / kBlock); }

__global__ void key_kernel(const Vec3* centroids, const uint32_t* ids, Vec3 lo, Vec3 scale, uint64_t* keys,
                           uint32_t* order, int n) {
  const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n) return;
  keys[i] = lbvh_key(centroids[i], lo, scale, ids[i]);
  order[i] = static_cast<uint32_t>(i);
}

__global__ void gather_kernel(const LbvhBox* boxes, const uint32_t* order, LbvhBox* leaf_boxes, int n) {
  const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i < n) leaf_boxes[i] = boxes[order[i]];
}

__global__ void radix_kernel(const uint64_t* keys, int n, LbvhInner* inner, uint32_t* parent) {
  const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i < n - 1) lbvh_radix_node(keys, n, i, inner, parent);
}

__global__ void climb_kernel(int n, const LbvhInner* inner, const uint32_t* parent, const LbvhBox* leaf_boxes,
                             LbvhBox* boxes, uint32_t* visits) {
  const int leaf = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  if (leaf < n) lbvh_climb(leaf, n, inner, parent, leaf_boxes, boxes, visits);
}

void check_launch() { TRACER_CUDA_CHECK(cudaGetLastError()); }

}  // namespace

GpuLbvh build_lbvh_on_gpu(const LbvhInput& in) {
  select_cuda_device();
  const auto t0 = std::chrono::steady_clock::now();
  const int n = static_cast<int>(in.boxes.size());
  GpuLbvh r;
  if (n < 2) {  // nothing to build in parallel
    r.tree = build_lbvh_tree(in, [](size_t count, const auto& fn) {
      for (size_t i = 0; i < count; ++i) fn(i);
    });
    return r;
  }
  Vec3 lo, scale;
  lbvh_frame(in.centroids, lo, scale);
  const DeviceBuffer<LbvhBox> boxes(in.boxes);
  const DeviceBuffer<Vec3> centroids(in.centroids);
  const DeviceBuffer<uint32_t> ids(in.ids);
  DeviceBuffer<uint64_t> keys(n);
  DeviceBuffer<uint32_t> order(n), parent(2 * size_t(n) - 1), visits(n - 1);
  DeviceBuffer<LbvhBox> leaf_boxes(n), inner_boxes(n - 1);
  DeviceBuffer<LbvhInner> inner(n - 1);
  visits.zero();

  const CudaEvent start, stop;
  TRACER_CUDA_CHECK(cudaEventRecord(start.event));
  key_kernel<<<blocks_for(n), kBlock>>>(centroids.get(), ids.get(), lo, scale, keys.get(), order.get(), n);
  check_launch();
  // Every key is distinct (the id breaks ties), so any correct sort gives the CPU's order.
  thrust::sort_by_key(thrust::device, keys.get(), keys.get() + n, order.get());
  gather_kernel<<<blocks_for(n), kBlock>>>(boxes.get(), order.get(), leaf_boxes.get(), n);
  check_launch();
  radix_kernel<<<blocks_for(n - 1), kBlock>>>(keys.get(), n, inner.get(), parent.get());
  check_launch();
  climb_kernel<<<blocks_for(n), kBlock>>>(n, inner.get(), parent.get(), leaf_boxes.get(), inner_boxes.get(),
                                          visits.get());
  check_launch();
  TRACER_CUDA_CHECK(cudaEventRecord(stop.event));
  r.build_seconds = seconds_between(start, stop);

  const std::vector<LbvhInner> host_inner = inner.download();
  const std::vector<LbvhBox> host_boxes = inner_boxes.download(), host_leaves = leaf_boxes.download();
  r.tree.order = order.download();
  r.tree.nodes.resize(2 * size_t(n) - 1);
  std::vector<uint32_t> queue(2 * size_t(n - 1));
  lbvh_lay_out(n, host_inner.data(), host_boxes.data(), host_leaves.data(), queue.data(), r.tree.nodes.data());
  r.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace tracer
