// A benchmark-only adapter to Embree 3 (Intel's kernels, Debian's libembree-dev), built when
// CMake finds it: the scene's triangles in one Embree scene, the same rays traced one at a
// time with rtcIntersect1 and rtcOccluded1 on the same threads, for `bench rays`' Embree
// row; build time and rates are medians of `repeats` runs. Never used to render.
#pragma once
#include <functional>
#include <vector>

#include "kernel/accel/primitive_hit.h"
#include "scene/scene.h"

namespace tracer {

struct EmbreeRow {
  double build_seconds = 0;
  double megabytes = 0;                            // peak bytes Embree reported through its memory monitor
  double primary = 0, incoherent = 0, shadow = 0;  // Mrays/s
  double same_primitive = 0;                       // fraction of closest hits on the primitive ours found
  double paired_build = 0;  // the median of our build's seconds over Embree's, in pairs from idle threads
};

bool embree_available();

// Only scenes made of triangles; InputError otherwise. With `our_build` (a build of ours,
// returning its seconds), paired_build alternates it with Embree's build, each from idle threads.
EmbreeRow embree_bench(const Scene& scene, const std::vector<Ray>& primary, const std::vector<Ray>& incoherent,
                       const std::vector<Ray>& shadow, const std::vector<float>& shadow_tmax,
                       const std::vector<Hit>& our_primary, const std::vector<Hit>& our_incoherent, int threads,
                       uint32_t repeats, const std::function<double()>& our_build = {});

}  // namespace tracer
