#include <cub/device/device_radix_sort.cuh>
#include <stdexcept>

#include "ray_order_gpu.h"

namespace tracer {
namespace {

constexpr uint32_t kBlock = 256;

// The key of each queued state's ray, and the queue copied beside it for the sort to carry.
__global__ void ray_order_key_kernel(RayOrderFrame frame, const Vec3* origin, const Vec3* dir, const uint32_t* queue,
                                     size_t n, uint32_t* keys, uint32_t* queue_copy) {
  const size_t q = static_cast<size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (q >= n) return;
  const uint32_t i = queue[q];
  keys[q] = ray_order_key(frame, origin[i], dir[i]);
  queue_copy[q] = i;
}

// The bytes of temporary storage CUB's sort of n pairs needs.
size_t sort_temp_bytes(size_t n) {
  size_t bytes = 0;
  cub::DoubleBuffer<uint32_t> keys(nullptr, nullptr), values(nullptr, nullptr);
  TRACER_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keys, values, static_cast<int>(n), 0,
                                                    static_cast<int>(kRayOrderKeyBits)));
  return bytes;
}

size_t checked_capacity(size_t capacity) {
  if (capacity > static_cast<size_t>(INT32_MAX)) throw std::length_error("GpuRaySorter: more than 2^31 - 1 rays");
  return capacity;
}

}  // namespace

GpuRaySorter::GpuRaySorter(size_t capacity)
    : capacity_(checked_capacity(capacity)),
      keys_{DeviceBuffer<uint32_t>(capacity), DeviceBuffer<uint32_t>(capacity)},
      queue_{DeviceBuffer<uint32_t>(capacity), DeviceBuffer<uint32_t>(capacity)},
      temp_(sort_temp_bytes(capacity)) {}

const uint32_t* GpuRaySorter::sort(const RayOrderFrame& frame, const Vec3* origin, const Vec3* dir,
                                   const uint32_t* queue, size_t n) {
  if (n > capacity_) throw std::length_error("GpuRaySorter::sort: a queue longer than the sorter's capacity");
  if (n == 0) return queue_[0].get();
  ray_order_key_kernel<<<static_cast<uint32_t>((n + kBlock - 1) / kBlock), kBlock>>>(frame, origin, dir, queue, n,
                                                                                     keys_[0].get(), queue_[0].get());
  TRACER_CUDA_CHECK(cudaGetLastError());
  cub::DoubleBuffer<uint32_t> keys(keys_[0].get(), keys_[1].get()), values(queue_[0].get(), queue_[1].get());
  size_t temp_bytes = temp_.bytes();
  TRACER_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp_.get(), temp_bytes, keys, values, static_cast<int>(n), 0,
                                                    static_cast<int>(kRayOrderKeyBits)));
  return values.Current();
}

}  // namespace tracer
