// The CPU's sort of rays by their keys (kernel/geom/ray_order_key.h), the counterpart of the
// GPU's (cuda/ray_order_gpu.h): of a ray set for `tracer bench rays`' row "bvh sorted", and of
// the stream schedule's queues (render.stream_order sorted, render_stream.cpp).
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

  // queue[0, n) (indices into origin and dir) put in the order of their rays' keys, entries of
  // equal keys in the queue's order, by the same sort.
  void sort_queue(uint32_t* queue, size_t n, const Vec3* origin, const Vec3* dir, const RayOrderFrame& frame,
                  int threads);

 private:
  // order_[0, n): value_of(i) for i in [0, n), stably sorted by key_of(i).
  template <class KeyOf, class ValueOf>
  void sort_by(size_t n, KeyOf key_of, ValueOf value_of, int threads);

  size_t capacity_;
  std::vector<uint32_t> key_, order_, next_key_, next_order_;
  std::vector<size_t> counts_;  // per thread and digit
};

}  // namespace tracer
