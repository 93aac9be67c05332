// The tracer's `--device cuda`: the scene's arrays rendered by cuda/gpu_film.cu, the kernel
// the self-contained runner launches too. With the strict flags of docs/determinism.md rule 1 the
// pixels equal the CPU's bit for bit.
#include "cuda_device.h"
#include "gpu_adaptive.h"
#include "gpu_film.h"
#include "render/render_cuda.h"

namespace tracer {

std::string cuda_device_description() { return describe_cuda_device(select_cuda_device()); }

namespace {

void report_run(const GpuRun& run, CudaRunInfo& info) {
  info.device = run.device;
  info.device_bytes = run.device_bytes;
  info.upload_seconds = run.upload_seconds;
  info.kernel_seconds = run.kernel_seconds;
  info.download_seconds = run.download_seconds;
}

// The scene's view with bvh's binary tree alone: `render --device cuda` walks it (the wide
// tree's kernels are timed by `bench rays --device cuda` and the pack's @bvh8 row).
SceneView binary_tree_view(const Scene& scene) {
  SceneView view = scene.view();
  view.wide_node_count = 0;
  return view;
}

}  // namespace

FilmBuffer render_cuda_film(const Scene& scene, SampleRange range, RenderStats& stats, CudaRunInfo& info) {
  GpuFilm r = render_film_on_gpu(scene, binary_tree_view(scene), range, scene.file);
  report_run(r.run, info);
  stats.rays = r.rays;
  stats.stream = r.stream;
  stats.nonfinite_samples = r.nonfinite;
  stats.overflow_samples = r.overflow;
  return std::move(r.film);
}

AdaptiveFilm render_cuda_adaptive(const Scene& scene, RenderStats& stats, CudaRunInfo& info) {
  GpuAdaptiveFilm r = render_adaptive_on_gpu(scene, binary_tree_view(scene), scene.file);
  report_run(r.run, info);
  stats.rays = r.rays;
  stats.stream = r.stream;
  stats.nonfinite_samples = adaptive_nonfinite_samples(r.film);
  stats.overflow_samples = adaptive_overflow_samples(r.film);
  return std::move(r.film);
}

Image render_cuda(const Scene& scene, RenderStats& stats, CudaRunInfo& info) {
  if (adaptive_render(scene.settings)) return resolve_adaptive(render_cuda_adaptive(scene, stats, info));
  const uint32_t spp = scene.settings.spp;
  return resolve_film(render_cuda_film(scene, {0, spp}, stats, info), spp);
}

}  // namespace tracer
