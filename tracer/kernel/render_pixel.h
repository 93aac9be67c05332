// One pixel from plain arrays: the single function that both schedulers (the OpenMP
// tile loop and, later, the CUDA grid) call. Samples are summed in index order, so the
// pixel cannot depend on the thread or block that computes it (DESIGN.md rule 5).
#pragma once
#include "debug_views.h"
#include "whitted.h"

namespace tracer {

struct PixelResult {
  Vec3 value;          // mean radiance over the samples
  uint32_t nonfinite;  // samples that came out NaN or infinite
};

TRACER_HD PixelResult render_pixel(const SceneView& scene, uint32_t px, uint32_t py,
                                   RayCounts& counts) {
  const RenderSettings& rs = scene.settings;
  const uint32_t pixel = py * rs.width + px;
  Vec3 sum = {0.0f, 0.0f, 0.0f};
  uint32_t nonfinite = 0;
  for (uint32_t s = 0; s < rs.spp; ++s) {
    float ox = 0.5f, oy = 0.5f, lu = 0.5f, lv = 0.5f;
    film_offset(rs.sampler, rs.grid_n, rs.seed, pixel, s, ox, oy);
    if (scene.features & kFeatureThinLens) sample_uniform2(rs.seed, pixel, s, kDimLens, lu, lv);
    const Ray ray = camera_ray(scene.camera, static_cast<float>(px) + ox,
                               static_cast<float>(py) + oy, lu, lv);
    ++counts.camera;
    const Vec3 value = rs.integrator == IntegratorKind::Whitted ? whitted_radiance(scene, ray, counts)
                                                                 : debug_view(scene, ray);
    if (!is_finite(value)) ++nonfinite;
    sum += value;
  }
  return {sum / static_cast<float>(rs.spp), nonfinite};
}

}  // namespace tracer
