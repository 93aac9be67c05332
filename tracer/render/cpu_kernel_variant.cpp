// One variant of the CPU kernel (tracer/render/cpu_kernel.h). CMake compiles this file once
// per (instruction set, feature set) with TRACER_VARIANT (the namespace and entry name),
// TRACER_VARIANT_ISA, TRACER_VARIANT_SET and TRACER_KERNEL_FEATURES (kernel/base/features.h)
// defined. The kernel's headers are included inside namespace TRACER_VARIANT, so this copy's
// inline functions have names of their own; the standard headers they use come first, at
// global scope, where they belong. The stream schedule's stages are the variant's second file
// (cpu_stream_variant.cpp): in this one they took GCC's inlining budget from the megakernel.
#include "render/cpu_variant_prelude.h"

namespace TRACER_VARIANT {
#include "kernel/accel/trace.h"
#include "kernel/integrator/render_pixel.h"
#include "kernel/integrator/stream.h"
}  // namespace TRACER_VARIANT

#include "render/cpu_variant_bytes.h"

namespace TRACER_VARIANT {
// The stream schedule's stages, compiled apart (cpu_stream_variant.cpp).
void stream_stage(const ::tracer::SceneView& view, uint32_t stage, const void* states, const uint32_t* queue,
                  size_t begin, size_t end, ::tracer::RayCounts& counts);
}  // namespace TRACER_VARIANT

namespace {

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
                                           TRACER_VARIANT::stream_stage};
  return variant;
}

}  // namespace tracer
