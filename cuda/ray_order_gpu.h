// A queue of ray states put in the order of their rays' sort keys on the device
// (kernel/geom/ray_order_key.h; CUB's radix sort over the key's 30 bits), so that the rays a
// warp traces start near each other and point the same way. Compiled per architecture, as
// CUB's sort tunes itself to each (cuda/ray_order_gpu.cu). Every call is queued on the default
// stream, so CUDA events around it time it.
#pragma once
#include <cstdint>

#include "device_buffer.h"
#include "kernel/geom/ray_order_key.h"

namespace tracer {

class GpuRaySorter {
 public:
  // Room for queues of up to `capacity` entries.
  explicit GpuRaySorter(size_t capacity);

  // queue[0, n) (indices into origin and dir) sorted by the keys of their rays in `frame`, in a
  // buffer of this object that stays valid until the next call; `queue` itself is not changed.
  const uint32_t* sort(const RayOrderFrame& frame, const Vec3* origin, const Vec3* dir, const uint32_t* queue,
                       size_t n);

 private:
  size_t capacity_;
  DeviceBuffer<uint32_t> keys_[2], queue_[2];
  DeviceBuffer<unsigned char> temp_;
};

}  // namespace tracer
