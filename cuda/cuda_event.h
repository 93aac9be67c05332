// A CUDA event that is destroyed even when a later call throws: kernel timings.
#pragma once
#include "cuda_check.h"

namespace tracer {

struct CudaEvent {
  cudaEvent_t event = nullptr;
  CudaEvent() { TRACER_CUDA_CHECK(cudaEventCreate(&event)); }
  ~CudaEvent() { cudaEventDestroy(event); }
  CudaEvent(const CudaEvent&) = delete;
  CudaEvent& operator=(const CudaEvent&) = delete;
};

// Milliseconds from `start` to `stop`, waiting for `stop`, in seconds.
inline double seconds_between(const CudaEvent& start, const CudaEvent& stop) {
  TRACER_CUDA_CHECK(cudaEventSynchronize(stop.event));
  float ms = 0.0f;
  TRACER_CUDA_CHECK(cudaEventElapsedTime(&ms, start.event, stop.event));
  return ms / 1000.0;
}

}  // namespace tracer
