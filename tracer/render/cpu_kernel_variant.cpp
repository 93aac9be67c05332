// One variant of the CPU kernel (tracer/render/cpu_kernel.h). CMake compiles this file once
// per (instruction set, feature set) with TRACER_VARIANT (the namespace and entry name),
// TRACER_VARIANT_ISA, TRACER_VARIANT_SET and TRACER_KERNEL_FEATURES (kernel/base/features.h)
// defined. The kernel's headers are included inside namespace TRACER_VARIANT, so this copy's
// inline functions have names of their own; the standard headers they use come first, at
// global scope, where they belong.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>  // GLM (the kernel's Vec3 and frames) at global scope; GLM_FORCE_INLINE
#include <glm/mat3x3.hpp>     // keeps each variant's uses inside its own instruction set
#include <glm/vec3.hpp>       // (CMakeLists.txt)
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "render/cpu_kernel.h"

namespace TRACER_VARIANT {
#include "kernel/accel/trace.h"
#include "kernel/integrator/render_pixel.h"
#include "kernel/integrator/stream.h"
}  // namespace TRACER_VARIANT

namespace {

namespace k = TRACER_VARIANT::tracer;

// The caller's bytes as this variant's types (the layouts are checked by the selection).
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

void render_tile(const tracer::SceneView& view, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1, uint32_t begin,
                 uint32_t end, tracer::FilmSum* film, tracer::RayCounts& counts) {
  const k::SceneView v = view_of(view);
  k::RayCounts c = load<k::RayCounts>(&counts, 0);
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x)
      store(film, static_cast<size_t>(y) * v.settings.width + x, k::render_pixel(v, x, y, begin, end, c));
  store(&counts, 0, c);
}

void render_pixels_halves(const tracer::SceneView& view, const uint32_t* pixels, size_t count, uint32_t begin,
                          uint32_t end, tracer::FilmSum* even, tracer::FilmSum* odd, tracer::RayCounts& counts) {
  const k::SceneView v = view_of(view);
  k::RayCounts c = load<k::RayCounts>(&counts, 0);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t p = pixels[i];
    k::FilmSum e = load<k::FilmSum>(even, p), o = load<k::FilmSum>(odd, p);
    k::render_pixel_halves(v, p % v.settings.width, p / v.settings.width, begin, end, e, o, c);
    store(even, p, e);
    store(odd, p, o);
  }
  store(&counts, 0, c);
}

void trace_closest(const tracer::SceneView& view, const tracer::Ray* rays, const float* tmax, size_t count,
                   tracer::Hit* hits) {
  const k::SceneView v = view_of(view);
  for (size_t i = 0; i < count; ++i) store(hits, i, k::trace_closest(v, load<k::Ray>(rays, i), tmax[i]));
}

void trace_any(const tracer::SceneView& view, const tracer::Ray* rays, const float* tmax, size_t count,
               uint8_t* occluded) {
  const k::SceneView v = view_of(view);
  for (size_t i = 0; i < count; ++i) occluded[i] = k::trace_any(v, load<k::Ray>(rays, i), tmax[i]) ? 1 : 0;
}

void stream_stage(const tracer::SceneView& view, uint32_t stage, const void* states, const uint32_t* queue,
                  size_t begin, size_t end, tracer::RayCounts& counts) {
  const k::SceneView v = view_of(view);
  const k::StreamStates st = load<k::StreamStates>(states, 0);
  k::RayCounts c = load<k::RayCounts>(&counts, 0);
  for (size_t q = begin; q < end; ++q) k::stream_stage(v, static_cast<k::StreamStage>(stage), st, queue[q], c);
  store(&counts, 0, c);
}

}  // namespace

namespace tracer {

const CpuKernelVariant& TRACER_VARIANT() {
  using namespace k;  // the FeatureBit names in TRACER_KERNEL_FEATURES
  static const CpuKernelVariant variant = {TRACER_VARIANT_ISA,
                                           TRACER_VARIANT_SET,
                                           TRACER_KERNEL_FEATURES,
                                           sizeof(k::SceneView),
                                           sizeof(k::Ray),
                                           sizeof(k::Hit),
                                           sizeof(k::FilmSum),
                                           sizeof(k::StreamStates),
                                           sizeof(k::WhittedVertex),
                                           render_tile,
                                           render_pixels_halves,
                                           trace_closest,
                                           trace_any,
                                           stream_stage};
  return variant;
}

}  // namespace tracer
