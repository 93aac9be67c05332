// The CPU's sort of a ray set by the rays' keys (kernel/geom/ray_order_key.h), for
// `tracer bench rays`' row "bvh sorted", the counterpart of the GPU's (cuda/ray_order_gpu.h).
#pragma once
#include <cstdint>
#include <vector>

#include "kernel/accel/primitive_hit.h"
#include "kernel/geom/ray_order_key.h"

namespace tracer {

class CpuRaySorter {
 public:
  // Room for sets of up to `capacity` rays, allocated here rather than in each sort.
  explicit CpuRaySorter(size_t capacity);

  // The permutation that lists `rays` by their keys in `frame`, rays of equal keys in the set's
  // order (a least-significant-digit radix sort on `threads` threads, the same permutation for
  // any count); valid until the next call.
  const std::vector<uint32_t>& sort(const std::vector<Ray>& rays, const RayOrderFrame& frame, int threads);

 private:
  size_t capacity_;
  std::vector<uint32_t> key_, order_, next_key_, next_order_;
  std::vector<size_t> counts_;  // per thread and digit
};

}  // namespace tracer
