// The trace code of the GPU stream schedule's closest-hit and any-hit kernels (cuda/gpu_stream.cu
// compiles a pair per row, named closest_hit_NAME_kernel and shadow_any_hit_NAME_kernel): a
// scene runs on the first row whose code holds what it needs (trace_code_needed), else on
// closest_hit_stage_kernel and shadow_any_hit_stage_kernel, which hold all of it. Each row
// is a structure with one set of shapes, held to 64 registers (docs/cuda.md, "Resource
// budgets", has each row's registers and spills); the planes are in every row, at the cost
// of no register. bvh_triangles walks the binary tree's pair records alone (a scene of
// triangles whose upload has none, its root a leaf, runs on the next row that holds the node
// walk); wide_bvh_triangles walks bvh's 8-wide tree where the device holds it
// (cuda/device_scene.h), and the binary tree's nodes where it does not.
#pragma once
#include "kernel/accel/trace_code.h"

namespace tracer {

#define TRACER_TRACE_VARIANTS(X)                                                                         \
  X(bvh_triangles, kTraceBvhPairs | kFeatureTriangle | kFeaturePlane | kTraceWatertight)                 \
  X(wide_bvh_triangles, kTraceWideBvh | kTraceBvh | kFeatureTriangle | kFeaturePlane | kTraceWatertight) \
  X(bvh_spheres, kTraceBvh | kFeatureSphere | kFeaturePlane)                                             \
  X(kdtree_triangles, kTraceKdtree | kFeatureTriangle | kFeaturePlane | kTraceWatertight)                \
  X(kdtree_spheres, kTraceKdtree | kFeatureSphere | kFeaturePlane)                                       \
  X(grid_triangles, kTraceGrid | kFeatureTriangle | kFeaturePlane | kTraceWatertight)                    \
  X(grid_spheres, kTraceGrid | kFeatureSphere | kFeaturePlane)

struct TraceVariant {
  const char* name;
  uint32_t code;  // a trace code (trace_code.h)
};

#define TRACER_TRACE_VARIANT_ROW(name, code) {#name, code},
inline constexpr TraceVariant kTraceVariants[] = {TRACER_TRACE_VARIANTS(TRACER_TRACE_VARIANT_ROW)};
#undef TRACER_TRACE_VARIANT_ROW
inline constexpr int kTraceVariantCount = sizeof kTraceVariants / sizeof kTraceVariants[0];

// The index of the first variant whose code holds `needed`, or -1: the full code.
constexpr int trace_variant_for(uint32_t needed) {
  for (int v = 0; v < kTraceVariantCount; ++v)
    if ((kTraceVariants[v].code & needed) == needed) return v;
  return -1;
}

// The variant a scene runs on: `features` is its FeatureBit mask; `wide_tree`: the device
// holds bvh's 8-wide tree; `pair_records`: it holds the binary tree's pair records
// (device_pair_records, render/device_bvh.h, says where an upload does).
constexpr int trace_variant_of(uint32_t features, const RenderSettings& rs, bool wide_tree, bool pair_records) {
  return trace_variant_for(trace_code_needed(features, rs.accel, rs.triangle_test, wide_tree, pair_records));
}

// The variant's name, "full" for -1.
inline const char* trace_variant_name(int variant) { return variant < 0 ? "full" : kTraceVariants[variant].name; }

}  // namespace tracer
