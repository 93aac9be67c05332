#include "render/ray_order_sort.h"

#include <omp.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace tracer {
namespace {

// A digit per bit level of the cells, six passes of 5 bits: 32 buckets, whose counts and
// write positions stay in the first-level cache through a pass.
constexpr uint32_t kDigitBits = kRayOrderCellBits, kDigits = 1u << kDigitBits;
static_assert(kRayOrderKeyBits % kDigitBits == 0, "whole digits");

size_t checked_capacity(size_t capacity) {
  if (capacity > UINT32_MAX) throw std::length_error("CpuRaySorter: more than 2^32 - 1 rays");
  return capacity;
}

}  // namespace

CpuRaySorter::CpuRaySorter(size_t capacity)
    : capacity_(checked_capacity(capacity)),
      key_(capacity),
      order_(capacity),
      next_key_(capacity),
      next_order_(capacity) {}

template <class KeyOf, class ValueOf>
void CpuRaySorter::sort_by(size_t n, KeyOf key_of, ValueOf value_of, int threads) {
  if (n > capacity_) throw std::length_error("CpuRaySorter: a set larger than the sorter's capacity");
  key_.resize(n), order_.resize(n), next_key_.resize(n), next_order_.resize(n);  // never beyond the capacity
#pragma omp parallel num_threads(threads)
  {
    const size_t t = static_cast<size_t>(omp_get_thread_num()), team = static_cast<size_t>(omp_get_num_threads());
    const size_t begin = n * t / team, end = n * (t + 1) / team;  // this thread's slice
    for (size_t i = begin; i < end; ++i) {
      key_[i] = key_of(i);
      order_[i] = value_of(i);
    }
#pragma omp single
    counts_.assign(team * kDigits, 0);
    for (uint32_t shift = 0; shift < kRayOrderKeyBits; shift += kDigitBits) {
      size_t* mine = &counts_[t * kDigits];  // counts, then where this slice's keys of each digit go
      std::fill(mine, mine + kDigits, size_t{0});
      for (size_t i = begin; i < end; ++i) ++mine[(key_[i] >> shift) & (kDigits - 1)];
#pragma omp barrier
#pragma omp single
      {
        size_t slot = 0;  // digit-major, then slice by slice: a stable order
        for (uint32_t d = 0; d < kDigits; ++d)
          for (size_t s = 0; s < team; ++s) slot += std::exchange(counts_[s * kDigits + d], slot);
      }
      for (size_t i = begin; i < end; ++i) {
        const size_t to = mine[(key_[i] >> shift) & (kDigits - 1)]++;
        next_key_[to] = key_[i];
        next_order_[to] = order_[i];
      }
#pragma omp barrier
#pragma omp single
      key_.swap(next_key_), order_.swap(next_order_);
    }
  }
}

const std::vector<uint32_t>& CpuRaySorter::sort(const std::vector<Ray>& rays, const RayOrderFrame& frame, int threads) {
  sort_by(
      rays.size(), [&](size_t i) { return ray_order_key(frame, rays[i].origin, rays[i].dir); },
      [](size_t i) { return static_cast<uint32_t>(i); }, threads);
  return order_;
}

void CpuRaySorter::sort_queue(uint32_t* queue, size_t n, const Vec3* origin, const Vec3* dir,
                              const RayOrderFrame& frame, int threads) {
  sort_by(
      n, [&](size_t i) { return ray_order_key(frame, origin[queue[i]], dir[queue[i]]); },
      [&](size_t i) { return queue[i]; }, threads);
  std::copy(order_.begin(), order_.end(), queue);
}

}  // namespace tracer
