// Every CUDA runtime call is checked: TRACER_CUDA_CHECK(cudaMalloc(...)) throws an error
// that names the call, where it was made and CUDA's own name and text for the error.
#pragma once
#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace tracer {

inline void cuda_check(cudaError_t error, const char* call, const char* file, int line) {
  if (error == cudaSuccess) return;
  throw std::runtime_error(std::string("CUDA error ") + cudaGetErrorName(error) + " (" + cudaGetErrorString(error) +
                           ") in " + call + " at " + file + ":" + std::to_string(line));
}

}  // namespace tracer

#define TRACER_CUDA_CHECK(call) ::tracer::cuda_check((call), #call, __FILE__, __LINE__)
