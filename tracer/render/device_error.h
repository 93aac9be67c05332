// Raised when a render asks for a device this machine or build cannot provide (no CUDA
// driver or GPU, a build without nvcc, a GPU too old or too small for the scene). `render`
// reports it as an error (exit 2, no output written); a `cuda` golden check reports it as
// skipped.
#pragma once
#include <stdexcept>
#include <string>

namespace tracer {

struct DeviceUnavailable : std::runtime_error {
  explicit DeviceUnavailable(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace tracer
