#include "golden/golden_check.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "image/image_io.h"
#include "image/pixel_hash.h"
#include "io/input_error.h"
#include "render/render_adaptive.h"
#include "render/render_cpu.h"
#include "render/render_cuda.h"
#include "scene/scene_loader.h"

namespace tracer {
namespace {

uint64_t count_nonfinite(const Image& image) {
  uint64_t n = 0;
  for (float v : image.rgb) n += std::isfinite(v) ? 0 : 1;
  return n;
}

}  // namespace

GoldenRender render_golden(const GoldenManifest& manifest, const GoldenEntry& entry, int threads, GoldenDevice device) {
  const std::string scene_path = manifest.scene_path(entry);
  if (!std::filesystem::is_regular_file(scene_path))
    throw InputError(manifest.path + ": goldens." + entry.name + ".scene: scene file " + scene_path +
                     " does not exist");
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = load_scene(scene_path, golden_overrides(manifest, entry));
  GoldenRender r;
  RenderStats stats;
  if (entry.image == GoldenImage::SampleMap) {
    if (!adaptive_render(scene.settings))
      throw InputError(manifest.path + ": goldens." + entry.name +
                       ".image: a sample map is an adaptive render's; set noise_threshold or target_error");
    CudaRunInfo info;
    r.image = adaptive_sample_map(device == GoldenDevice::Cuda ? render_cuda_adaptive(scene, stats, info)
                                                               : render_cpu_adaptive(scene, threads, stats));
  } else if (device == GoldenDevice::Cuda) {
    CudaRunInfo info;
    r.image = render_cuda(scene, stats, info);
  } else {
    r.image = render_cpu(scene, threads, stats);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.nonfinite_samples = stats.nonfinite_samples;
  r.overflow_samples = stats.overflow_samples;
  r.hash = pixel_hash(r.image);
  r.options = recorded_options(scene.settings, scene.background.kind);
  return r;
}

GoldenOutcome golden_error(const GoldenEntry& entry, const std::string& message, GoldenStatus status) {
  GoldenOutcome o;
  o.name = entry.name;
  o.status = status;
  o.message = message;
  return o;
}

GoldenOutcome judge_golden(const GoldenManifest& manifest, const GoldenEntry& entry, const GoldenRender& render) {
  GoldenOutcome o;
  o.name = entry.name;
  o.nonfinite_values = render.nonfinite_samples + count_nonfinite(render.image);
  o.overflow_samples = render.overflow_samples;
  const std::string image_path = manifest.image_path(entry);
  const std::string update = "; run `tracer golden update --filter '^" + entry.name + "$'` to create it";
  if (entry.hash.empty()) return golden_error(entry, "new golden: the manifest has no hash yet" + update);
  if (!std::filesystem::exists(image_path))
    return golden_error(entry, image_path + ": the reference image does not exist" + update);
  try {
    o.reference = read_image(image_path);
  } catch (const InputError& e) {
    return golden_error(entry, std::string(e.what()) + " (corrupt reference image)");
  }
  const std::string reference_hash = pixel_hash(*o.reference);
  if (reference_hash != entry.hash)
    return golden_error(entry, image_path + ": its pixels hash to " + reference_hash + ", but " + manifest.path +
                                   " records " + entry.hash + " (corrupt, or edited without `tracer golden update`)");

  CompareOptions exact;
  exact.fail = 0.0f;
  exact.warn = 0.0f;
  CompareOptions options = exact;
  if (entry.tolerance) {
    options.fail = options.warn = entry.tolerance->fail;
    options.failpercent = options.warnpercent = entry.tolerance->failpercent;
  }
  o.metrics = compare_images(render.image, *o.reference, options);
  const bool identical = render.hash == entry.hash && o.metrics->bit_identical;
  if (o.nonfinite_values > 0) {
    o.status = GoldenStatus::Fail;
    o.message = std::to_string(o.nonfinite_values) + " NaN/inf samples or values in the new image";
  } else if (o.overflow_samples > 0) {
    o.status = GoldenStatus::Fail;
    o.message = std::to_string(o.overflow_samples) + " samples of the new image beyond the film's range (2^30)";
  } else if (!o.metrics->same_size) {
    o.status = GoldenStatus::Fail;
    o.message = "size differs: new " + std::to_string(render.image.width) + "x" + std::to_string(render.image.height) +
                ", reference " + std::to_string(o.reference->width) + "x" + std::to_string(o.reference->height);
  } else if (identical) {
    o.status = GoldenStatus::Pass;
    o.message = "identical (" + entry.hash + ")";
  } else if (entry.tolerance && o.metrics->verdict != Verdict::Fail) {
    o.status = GoldenStatus::Pass;
    o.message = "within tolerance (" + describe(*o.metrics) + "): " + entry.tolerance->why;
  } else {
    o.status = GoldenStatus::Fail;
    const uint64_t differing = entry.tolerance ? o.metrics->pixels_over_fail : o.metrics->pixels_not_identical;
    char detail[128];
    std::snprintf(detail, sizeof detail, " (max error %.4g at (%d, %d), PSNR %.1f dB)", o.metrics->max_error,
                  o.metrics->max_x, o.metrics->max_y, o.metrics->psnr);
    o.message = std::to_string(differing) + " of " + std::to_string(o.metrics->pixels) + " pixels differ" +
                (entry.tolerance ? " beyond the tolerance" : "") + detail;
  }
  return o;
}

}  // namespace tracer
