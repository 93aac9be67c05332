// One pixel from plain arrays: the single function that both schedulers (the OpenMP
// tile loop and the CUDA grid) call. render_sample computes one sample of one pixel;
// render_pixel adds a range of them into the pixel's fixed-point film sum (film.h), so a
// pixel cannot depend on the thread, block, device or sample range that computes it
// (docs/determinism.md rule 5).
#pragma once
#include "kernel/base/film.h"
#include "kernel/integrator/debug_views.h"
#include "kernel/integrator/path.h"
#include "kernel/integrator/whitted.h"

namespace tracer {

// The camera ray of sample s of pixel (px, py), through its film offset and lens point.
TRACER_HD Ray sample_camera_ray(const SceneView& scene, uint32_t px, uint32_t py, uint32_t s, RayCounts& counts) {
  const RenderSettings& rs = scene.settings;
  const uint32_t pixel = py * rs.width + px;
  float ox = 0.5f, oy = 0.5f, lu = 0.5f, lv = 0.5f;
  film_offset(rs.sampler, rs.grid_n, rs.seed, pixel, s, ox, oy);
  if (uses_feature(scene.features, kFeatureThinLens)) draw_uniform2(rs.sampler, rs.seed, pixel, s, kDimLens, lu, lv);
  ++counts.camera;
  return camera_ray(scene.camera, static_cast<float>(px) + ox, static_cast<float>(py) + oy, lu, lv);
}

// Sample s of pixel (px, py) by the integrator kKind: Whitted, Path, or any of the debug
// views (Normals, Albedo and Depth share debug_view, which reads the scene's). A GPU kernel
// compiled for one integrator (cuda/gpu_film.cu) holds only its code: Whitted's stack of
// kMaxDepth + 2 rays is not in the path tracer's, nor the path's BSDFs in the views'.
template <IntegratorKind kKind, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD Vec3 render_sample_as(const SceneView& scene, uint32_t px, uint32_t py, uint32_t s, RayCounts& counts) {
  const Ray ray = sample_camera_ray(scene, px, py, s, counts);
  if constexpr (kKind == IntegratorKind::Whitted)
    return whitted_radiance<kFeatures>(scene, ray, counts);
  else if constexpr (kKind == IntegratorKind::Path)
    return path_radiance<kFeatures>(scene, ray, py * scene.settings.width + px, s, counts);
  else
    return debug_view(scene, ray, trace_closest(scene, ray, kInfinity));
}

// Sample s of pixel (px, py): the radiance the scene's integrator returns along its camera ray.
TRACER_HD Vec3 render_sample(const SceneView& scene, uint32_t px, uint32_t py, uint32_t s, RayCounts& counts) {
  switch (scene.settings.integrator) {
    case IntegratorKind::Whitted: return render_sample_as<IntegratorKind::Whitted>(scene, px, py, s, counts);
    case IntegratorKind::Path: return render_sample_as<IntegratorKind::Path>(scene, px, py, s, counts);
    default: return render_sample_as<IntegratorKind::Normals>(scene, px, py, s, counts);
  }
}

// Samples [sample_begin, sample_end) of pixel (px, py) by the integrator kKind
// (render_sample_as), added into a fresh film sum.
template <IntegratorKind kKind, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD FilmSum render_pixel_as(const SceneView& scene, uint32_t px, uint32_t py, uint32_t sample_begin,
                                  uint32_t sample_end, RayCounts& counts) {
  FilmSum sum = {{0, 0, 0}, 0u, 0u};
  for (uint32_t s = sample_begin; s < sample_end; ++s)
    film_add(sum, render_sample_as<kKind, kFeatures>(scene, px, py, s, counts));
  return sum;
}

// Samples [sample_begin, sample_end) of pixel (px, py), added into a fresh film sum.
TRACER_HD FilmSum render_pixel(const SceneView& scene, uint32_t px, uint32_t py, uint32_t sample_begin,
                               uint32_t sample_end, RayCounts& counts) {
  FilmSum sum = {{0, 0, 0}, 0u, 0u};
  for (uint32_t s = sample_begin; s < sample_end; ++s) film_add(sum, render_sample(scene, px, py, s, counts));
  return sum;
}

// Samples [sample_begin, sample_end) of pixel (px, py) by the integrator kKind, even samples
// added into `even` and odd ones into `odd` (adaptive sampling's half sums). Their sum is
// render_pixel's unless a half stays inside the film's range where the whole would leave it
// (sums near 2^62 units).
template <IntegratorKind kKind, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD void render_pixel_halves_as(const SceneView& scene, uint32_t px, uint32_t py, uint32_t sample_begin,
                                      uint32_t sample_end, FilmSum& even, FilmSum& odd, RayCounts& counts) {
  for (uint32_t s = sample_begin; s < sample_end; ++s)
    film_add(s % 2u == 0u ? even : odd, render_sample_as<kKind, kFeatures>(scene, px, py, s, counts));
}

// render_pixel_halves_as by the scene's integrator.
TRACER_HD void render_pixel_halves(const SceneView& scene, uint32_t px, uint32_t py, uint32_t sample_begin,
                                   uint32_t sample_end, FilmSum& even, FilmSum& odd, RayCounts& counts) {
  switch (scene.settings.integrator) {
    case IntegratorKind::Whitted:
      return render_pixel_halves_as<IntegratorKind::Whitted>(scene, px, py, sample_begin, sample_end, even, odd,
                                                             counts);
    case IntegratorKind::Path:
      return render_pixel_halves_as<IntegratorKind::Path>(scene, px, py, sample_begin, sample_end, even, odd, counts);
    default:
      return render_pixel_halves_as<IntegratorKind::Normals>(scene, px, py, sample_begin, sample_end, even, odd,
                                                             counts);
  }
}

}  // namespace tracer
