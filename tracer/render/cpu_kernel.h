// The CPU kernel in compiled variants (the idea of Cycles' per-ISA kernels and kernel
// feature bits): tracer/render/cpu_kernel_variant.cpp is compiled once per instruction set
// (x86-64, AVX2, AVX-512; the host's own on other CPUs) and per feature set (CMake's
// TRACER_CPU_FEATURE_SETS), each copy in its own namespace so that no inline function
// compiled for AVX2 can stand in for the baseline's. A scene runs on the best instruction
// set the CPU has and the smallest feature set that holds every feature it uses; a scene
// without a feature runs no code for it. Every variant gives the same images bit for bit
// (the same operations in the same order, no FMA; tests/determinism/test_cpu_kernels.cpp).
//
// This header names no kernel type: the variants exchange plain bytes whose layout each
// checks (view_bytes, ...), since each variant has its own copy of the kernel's types.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tracer {

struct SceneView;
struct Ray;
struct Hit;
struct FilmSum;
struct RayCounts;

struct CpuKernelVariant {
  const char* isa;          // "x86-64", "avx2", "avx512" or "native"
  const char* feature_set;  // "generic" or a set of TRACER_CPU_FEATURE_SETS
  uint32_t features;        // the FeatureBit mask compiled in
  size_t view_bytes, ray_bytes, hit_bytes, film_sum_bytes, stream_states_bytes, whitted_vertex_bytes;
  // Pixels [x0, x1) x [y0, y1), samples [begin, end), into film (row-major, `width` wide).
  void (*render_tile)(const SceneView& view, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1, uint32_t begin,
                      uint32_t end, FilmSum* film, RayCounts& counts);
  // Samples [begin, end) of each of `count` pixels (indices y * width + x), into the even
  // and odd half sums at those indices (adaptive sampling).
  void (*render_pixels_halves)(const SceneView& view, const uint32_t* pixels, size_t count, uint32_t begin,
                               uint32_t end, FilmSum* even, FilmSum* odd, RayCounts& counts);
  // trace_closest over t in (0, tmax[i]] (hits), or trace_any (occluded), for every ray.
  void (*trace_closest)(const SceneView& view, const Ray* rays, const float* tmax, size_t count, Hit* hits);
  void (*trace_any)(const SceneView& view, const Ray* rays, const float* tmax, size_t count, uint8_t* occluded);
  // The stream schedule's `stage` (kernel/integrator/stream.h's StreamStage) for the states
  // queue[begin, end) of `states` (a StreamStates).
  void (*stream_stage)(const SceneView& view, uint32_t stage, const void* states, const uint32_t* queue, size_t begin,
                       size_t end, RayCounts& counts);
};

// Every variant in this binary.
const std::vector<const CpuKernelVariant*>& cpu_kernel_variants();

// The variant for a scene using `features`: the instruction set named by the environment
// variable TRACER_CPU_ISA when set (an InputError when this CPU or build lacks it), else the
// best this CPU runs; with `generic`, the all-features build, else the smallest feature set
// that holds `features`.
const CpuKernelVariant& cpu_kernel_for(uint32_t features, bool generic = false);

// For each instruction set this CPU runs, in build order (the baseline first), the variant
// cpu_kernel_for would choose with it: for benchmarks and the identity tests.
std::vector<const CpuKernelVariant*> cpu_kernels_per_isa(uint32_t features, bool generic = false);

// "avx2/plain" and the like, for --stats, info and benchmarks.
std::string cpu_kernel_name(const CpuKernelVariant& v);

}  // namespace tracer
