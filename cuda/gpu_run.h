// What a render on the GPU reports besides its film: the device, the memory it took and
// where the time went. Plain C++: the tracer copies it into its CudaRunInfo, the runner prints it.
#pragma once
#include <string>

namespace tracer {

struct GpuRun {
  std::string device;       // "NVIDIA H100 80GB HBM3 (sm_90, 79.1 GiB)"
  size_t device_bytes = 0;  // scene arrays, film and counters (and an adaptive render's maps) on the device
  double upload_seconds = 0, kernel_seconds = 0, download_seconds = 0;
};

}  // namespace tracer
