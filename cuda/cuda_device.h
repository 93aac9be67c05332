// Picks the CUDA device a render runs on (device 0 of those CUDA_VISIBLE_DEVICES shows)
// and describes it; DeviceUnavailable when there is no driver, no device, or one older
// than the sm_80 this build targets.
#pragma once
#include <cuda_runtime.h>

#include <cstdio>
#include <string>

#include "cuda_check.h"
#include "render/device_error.h"

namespace tracer {

inline cudaDeviceProp select_cuda_device() {
  int count = 0;
  const cudaError_t error = cudaGetDeviceCount(&count);
  if (error != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error state
    throw DeviceUnavailable(std::string("no usable CUDA device: ") + cudaGetErrorString(error));
  }
  if (count == 0) throw DeviceUnavailable("no CUDA device is present");
  cudaDeviceProp prop{};
  TRACER_CUDA_CHECK(cudaGetDeviceProperties(&prop, 0));
  if (prop.major < 8)
    throw DeviceUnavailable(std::string(prop.name) + " has compute capability " + std::to_string(prop.major) + "." +
                            std::to_string(prop.minor) + "; this build runs on sm_80 and newer");
  TRACER_CUDA_CHECK(cudaSetDevice(0));
  return prop;
}

inline std::string describe_cuda_device(const cudaDeviceProp& prop) {
  char text[256];
  std::snprintf(text, sizeof text, "%s (sm_%d%d, %.1f GiB)", prop.name, prop.major, prop.minor,
                static_cast<double>(prop.totalGlobalMem) / (1024.0 * 1024.0 * 1024.0));
  return text;
}

// DeviceUnavailable naming `label` when `bytes` exceed the device's free memory.
inline void require_free_device_memory(size_t bytes, const std::string& label, const std::string& device) {
  size_t free_bytes = 0, total_bytes = 0;
  TRACER_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  if (bytes > free_bytes)
    throw DeviceUnavailable(label + ": the scene needs " + std::to_string(bytes >> 20) + " MiB of device memory; " +
                            device + " has " + std::to_string(free_bytes >> 20) + " MiB free");
}

}  // namespace tracer
