// Where a path tracer's error comes from: each sample's radiance split by the estimator that
// added it (emission a BSDF-sampled ray hit, the environment or a declared light a ray
// escaped to, next-event estimation, a mirror image), by the scattering vertices before the
// light (0: the light seen directly, 1: direct lighting, ..., 4 for four or more) and by the
// last two of those vertices' materials (diffuse: lambert; specular: a smooth mirror or glass;
// glossy: everything else, the mixed materials included). The split reproduces the megakernel's
// loop over the kernel's own path_shade, so the classes of a sample add up to its radiance
// (bit for bit where a vertex adds at most one term; `tracer bench variance` and docs/path.md).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kernel/scene/scene_view.h"

namespace tracer {

enum class PathEstimator : uint32_t { Emission, Escape, LightSample, MirrorImage, kCount };
enum class VertexLobe : uint32_t { Diffuse, Glossy, Specular };

constexpr uint32_t kSplitBounceClasses = 5;  // 0, 1, 2, 3, 4 or more vertices before the light
constexpr uint32_t kSplitLobeCodes = 13;     // none; one lobe (3); the last two (9)
constexpr uint32_t kPathClasses = static_cast<uint32_t>(PathEstimator::kCount) * kSplitBounceClasses * kSplitLobeCodes;

// A class's index below kPathClasses, and its name ("light sample, 2 vertices, diffuse > specular").
uint32_t path_class(PathEstimator estimator, uint32_t vertices, const VertexLobe* last_two);
std::string path_class_name(uint32_t path_class);
const char* path_estimator_name(PathEstimator estimator);  // "light sample"
PathEstimator path_class_estimator(uint32_t path_class);
uint32_t path_class_vertices(uint32_t path_class);  // 4 stands for four or more

// Sample s of pixel (px, py) by the path integrator, each term handed to `add` with its class;
// returns the sample's radiance, as render_sample returns it.
Vec3 split_path_sample(const SceneView& scene, uint32_t px, uint32_t py, uint32_t s,
                       const std::function<void(uint32_t path_class, Vec3 radiance)>& add);

// Per class, the sum over samples [begin, end) of every pixel (3 doubles per pixel, row by row);
// a class no sample reached has no image. `threads` 0: all.
struct SplitImages {
  uint32_t width = 0, height = 0, samples = 0;
  std::vector<std::unique_ptr<std::vector<double>>> sums;  // kPathClasses entries
};
SplitImages render_split(const SceneView& scene, uint32_t sample_begin, uint32_t sample_end, int threads,
                         const std::function<void(uint64_t done, uint64_t total)>& progress);

}  // namespace tracer
