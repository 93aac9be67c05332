// A copy of the kernel in its own namespace (as tracer/render/cpu_kernel_variant.cpp) with
// TRACER_TRACE_HOOK appending each query's ray to the recording.
#include <vector>

#include "bench/ray_recorder.h"
#include "render/cpu_variant_prelude.h"

static tracer::RecordedRays* g_recording = nullptr;  // one recording at a time, on one thread

static void record_traced_ray(const float* origin_dir, float tmax, bool any) {
  std::vector<float>& out = any ? g_recording->any : g_recording->closest;
  out.insert(out.end(), origin_dir, origin_dir + 6);
  out.push_back(tmax);
}

#define TRACER_TRACE_HOOK(ray, tmax, any)                                                                    \
  do {                                                                                                       \
    const float origin_dir[6] = {ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z}; \
    ::record_traced_ray(origin_dir, tmax, any);                                                              \
  } while (0)

namespace tracer_ray_recorder {
#include "kernel/integrator/render_pixel.h"
}  // namespace tracer_ray_recorder

namespace tracer {

RecordedRays record_rays(const SceneView& view, uint32_t sample_begin, uint32_t sample_end) {
  namespace k = tracer_ray_recorder::tracer;
  k::SceneView v;
  std::memcpy(static_cast<void*>(&v), &view, sizeof v);
  RecordedRays rays;
  g_recording = &rays;
  k::RayCounts counts{};
  for (uint32_t y = 0; y < v.settings.height; ++y)
    for (uint32_t x = 0; x < v.settings.width; ++x) k::render_pixel(v, x, y, sample_begin, sample_end, counts);
  g_recording = nullptr;
  return rays;
}

}  // namespace tracer
