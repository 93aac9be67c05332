#include "bench/variance_split.h"

#include <omp.h>

#include <atomic>
#include <mutex>

#include "kernel/integrator/render_pixel.h"

namespace tracer {
namespace {

constexpr const char* kEstimatorNames[] = {"emission hit", "escape", "light sample", "mirror image"};
constexpr const char* kLobeNames[] = {"diffuse", "glossy", "specular"};

VertexLobe lobe_of(const Material& m) {
  if (is_specular(m)) return VertexLobe::Specular;
  return m.kind == MaterialKind::Lambert ? VertexLobe::Diffuse : VertexLobe::Glossy;
}

// The materials of the last two scattering vertices of a path, oldest first.
struct LobeHistory {
  VertexLobe last_two[2] = {VertexLobe::Diffuse, VertexLobe::Diffuse};
  void push(VertexLobe l) { last_two[0] = last_two[1], last_two[1] = l; }
};

}  // namespace

const char* path_estimator_name(PathEstimator e) { return kEstimatorNames[static_cast<uint32_t>(e)]; }

uint32_t path_class(PathEstimator estimator, uint32_t vertices, const VertexLobe* last_two) {
  const uint32_t bounce = vertices < kSplitBounceClasses ? vertices : kSplitBounceClasses - 1;
  const uint32_t a = static_cast<uint32_t>(last_two[0]), b = static_cast<uint32_t>(last_two[1]);
  const uint32_t lobes = vertices == 0 ? 0u : vertices == 1 ? 1u + b : 4u + 3u * a + b;
  return (static_cast<uint32_t>(estimator) * kSplitBounceClasses + bounce) * kSplitLobeCodes + lobes;
}

PathEstimator path_class_estimator(uint32_t c) {
  return static_cast<PathEstimator>(c / (kSplitBounceClasses * kSplitLobeCodes));
}

uint32_t path_class_vertices(uint32_t c) { return c / kSplitLobeCodes % kSplitBounceClasses; }

std::string path_class_name(uint32_t c) {
  const uint32_t vertices = path_class_vertices(c), lobes = c % kSplitLobeCodes;
  std::string name = std::string(path_estimator_name(path_class_estimator(c))) + ", " + std::to_string(vertices) +
                     (vertices == kSplitBounceClasses - 1 ? "+" : "") + " vertices";
  if (lobes >= 4) name += std::string(", ") + kLobeNames[(lobes - 4) / 3] + " > " + kLobeNames[(lobes - 4) % 3];
  if (lobes >= 1 && lobes < 4) name += std::string(", ") + kLobeNames[lobes - 1];
  return name;
}

// path_radiance's loop (kernel/integrator/path.h), each term taken where it is added.
Vec3 split_path_sample(const SceneView& scene, uint32_t px, uint32_t py, uint32_t s,
                       const std::function<void(uint32_t, Vec3)>& add) {
  constexpr uint32_t kCode = full_trace_code<TRACER_KERNEL_FEATURES>();
  RayCounts counts{};
  PathState st = path_start(sample_camera_ray(scene, px, py, s, counts));
  const uint32_t pixel = py * scene.settings.width + px;
  Vec3 total = {0.0f, 0.0f, 0.0f};
  LobeHistory history;
  const auto take = [&](PathEstimator e, uint32_t vertices, const VertexLobe* lobes, Vec3 radiance) {
    if (radiance == Vec3{0.0f, 0.0f, 0.0f}) return;
    total += radiance;
    add(path_class(e, vertices, lobes), radiance);
  };
  for (;;) {
    const Hit hit = trace_closest<kCode>(scene, st.ray, kInfinity);
    const uint32_t vertices = st.depth;
    st.radiance = {0.0f, 0.0f, 0.0f};  // what this vertex adds, alone
    ShadowQuery shadow;
    MirrorQuery image;
    const PathStep step = path_shade(scene, pixel, s, hit, st, shadow, image, counts);
    take(hit.prim == kNoHit ? PathEstimator::Escape : PathEstimator::Emission, vertices, history.last_two, st.radiance);
    if (hit.prim == kNoHit) return total;
    const VertexLobe here = lobe_of(scene.materials[scene.primitives[hit.prim].material]);
    const VertexLobe with_here[2] = {history.last_two[1], here};
    const VertexLobe via_mirror[2] = {here, VertexLobe::Specular};
    const uint8_t kinds = static_cast<uint8_t>((step.shadow ? unsigned{kShadowLight} : 0u) |
                                               (step.mirror ? unsigned{kShadowMirror} : 0u));
    const uint8_t clear = trace_shadows<kCode>(scene, kinds, shadow, &image, 0);
    if (clear & kShadowLight) take(PathEstimator::LightSample, vertices + 1, with_here, shadow.contribution);
    if (clear & kShadowMirror) take(PathEstimator::MirrorImage, vertices + 2, via_mirror, image.to_mirror.contribution);
    if (!step.alive) return total;
    history.push(here);
  }
}

SplitImages render_split(const SceneView& scene, uint32_t sample_begin, uint32_t sample_end, int threads,
                         const std::function<void(uint64_t, uint64_t)>& progress) {
  SplitImages out;
  out.width = scene.settings.width;
  out.height = scene.settings.height;
  out.samples = sample_end - sample_begin;
  out.sums.resize(kPathClasses);
  std::atomic<std::vector<double>*> images[kPathClasses] = {};
  std::mutex allocation;
  const size_t floats = size_t{out.width} * out.height * 3;
  // A class's image on its first term; each pixel is written by the one thread that owns its row.
  const auto image_of = [&](uint32_t c) {
    std::vector<double>* image = images[c].load(std::memory_order_acquire);
    if (image) return image;
    std::lock_guard<std::mutex> lock(allocation);
    if (!out.sums[c]) out.sums[c] = std::make_unique<std::vector<double>>(floats, 0.0);
    images[c].store(out.sums[c].get(), std::memory_order_release);
    return out.sums[c].get();
  };
  std::atomic<uint64_t> rows_done{0};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int64_t y = 0; y < static_cast<int64_t>(out.height); ++y) {
    for (uint32_t x = 0; x < out.width; ++x) {
      const size_t at = (static_cast<size_t>(y) * out.width + x) * 3;
      for (uint32_t s = sample_begin; s < sample_end; ++s)
        split_path_sample(scene, x, static_cast<uint32_t>(y), s, [&](uint32_t c, Vec3 radiance) {
          if (!is_finite(radiance)) return;  // as the film leaves out a sample that is not finite
          std::vector<double>& image = *image_of(c);
          image[at] += radiance.x, image[at + 1] += radiance.y, image[at + 2] += radiance.z;
        });
    }
    const uint64_t done = ++rows_done;
#pragma omp critical(variance_split_progress)
    if (progress) progress(done, out.height);
  }
  return out;
}

}  // namespace tracer
