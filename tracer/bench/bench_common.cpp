#include "bench/bench_common.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "image/image_io.h"
#include "io/input_error.h"
#include "options/number_text.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"

namespace tracer {

constexpr uint64_t kReferenceSeedOffset = 0x9E3779B97F4A7C15ull;  // keeps the reference's samples independent

TimedRender timed_render(const Scene& scene, int threads, int repeats) {
  TimedRender r;
  r.seconds = median_seconds(static_cast<uint32_t>(repeats), [&] {
    RenderStats stats;
    r.image = render_cpu(scene, threads, stats);
    r.rays = stats.rays.camera + stats.rays.secondary + stats.rays.shadow;
  });
  return r;
}

ImageError image_error(const Image& image, const Image& reference) {
  ImageError e;
  for (size_t i = 0; i < image.rgb.size(); ++i) {
    const double d = static_cast<double>(image.rgb[i]) - reference.rgb[i];
    const double shown = std::clamp(static_cast<double>(image.rgb[i]), 0.0, 1.0) -
                         std::clamp(static_cast<double>(reference.rgb[i]), 0.0, 1.0);
    e.rmse += d * d;
    e.display_rmse += shown * shown;
    e.rel_mse += d * d / (static_cast<double>(reference.rgb[i]) * reference.rgb[i] + 0.01);
  }
  const double n = static_cast<double>(image.rgb.size());
  e.rmse = std::sqrt(e.rmse / n);
  e.display_rmse = std::sqrt(e.display_rmse / n);
  e.rel_mse /= n;
  return e;
}

std::string bench_reference_dir() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = (ec ? std::filesystem::path(".") : self.parent_path()) / "bench-refs";
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the benchmark reference directory: " + ec.message());
  return dir.string();
}

Image reference_image(const std::string& scene_path, RenderOverrides overrides, const std::string& ref_file,
                      uint64_t ref_spp, int threads, const std::string& save_as) {
  const Scene probe = load_scene(scene_path, overrides);
  if (ref_spp > UINT32_MAX)
    throw InputError("--ref-spp: the default reference would take " + std::to_string(ref_spp) +
                     " samples per pixel, over " + std::to_string(UINT32_MAX) + "; give --ref-spp or --ref");
  if (!ref_file.empty()) {
    Image ref = read_image(ref_file);
    if (ref.width != probe.settings.width || ref.height != probe.settings.height)
      throw InputError(ref_file + ": the reference is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) +
                       ", the renders " + std::to_string(probe.settings.width) + "x" +
                       std::to_string(probe.settings.height));
    std::printf("reference: %s\n", ref_file.c_str());
    return ref;
  }
  overrides.spp = static_cast<uint32_t>(ref_spp);
  overrides.seed = probe.settings.seed + kReferenceSeedOffset;
  if (probe.settings.sampler == SamplerKind::Center || probe.settings.sampler == SamplerKind::Grid)
    overrides.sampler = SamplerKind::Stochastic;
  const TimedRender r = timed_render(load_scene(scene_path, overrides), threads);
  const std::string path = (std::filesystem::path(bench_reference_dir()) / save_as).string();
  write_image(r.image, path);
  std::printf("reference: %llu spp, %.2f s, saved as %s (give --ref %s to reuse it)\n",
              static_cast<unsigned long long>(ref_spp), r.seconds, path.c_str(), path.c_str());
  return r.image;
}

std::vector<uint32_t> parse_spp_list(const std::string& option, const std::string& text) {
  std::vector<uint32_t> out;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::optional<uint64_t> v = parse_count(item, UINT32_MAX);
    if (!v || *v == 0)
      throw InputError(option + " " + text + ": expected a comma-separated list of sample counts, each " +
                       count_range(1, UINT32_MAX));
    out.push_back(static_cast<uint32_t>(*v));
  }
  if (out.empty()) throw InputError(option + ": expected at least one sample count");
  return out;
}

}  // namespace tracer
