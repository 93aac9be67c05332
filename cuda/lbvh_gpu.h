// The LBVH built on the GPU from the kernel/accel/lbvh.h steps that the CPU builds run (keys,
// radix nodes and bottom-up boxes as CUDA grids; the keys sorted on the device), laid out
// by the same lbvh_lay_out on the host. Plain C++ header: no CUDA types.
#pragma once
#include "accel/lbvh_build.h"

namespace tracer {

struct GpuLbvh {
  LbvhTree tree;
  double build_seconds = 0;  // keys to boxes on the device (CUDA events), without transfers and layout
  double total_seconds = 0;  // upload, build, download and layout
};

// DeviceUnavailable without a usable GPU; std::runtime_error naming a failing CUDA call.
GpuLbvh build_lbvh_on_gpu(const LbvhInput& in);

}  // namespace tracer
