// A CPU kernel variant's view of the caller's bytes as its own types (the layouts are checked
// by the selection, cpu_kernel_select.cpp). Included after the kernel's headers in a variant's files.
#pragma once
#include <cstring>

namespace {

namespace k = TRACER_VARIANT::tracer;

k::SceneView view_of(const tracer::SceneView& view) {
  k::SceneView v;
  std::memcpy(static_cast<void*>(&v), &view, sizeof v);
  return v;
}

template <typename T>
T load(const void* array, size_t i) {
  T value;
  std::memcpy(&value, static_cast<const unsigned char*>(array) + i * sizeof(T), sizeof(T));
  return value;
}

template <typename T>
void store(void* array, size_t i, const T& value) {
  std::memcpy(static_cast<unsigned char*>(array) + i * sizeof(T), &value, sizeof(T));
}

}  // namespace
