// The code a trace query is compiled with (the idea of Cycles' kernel feature bits, applied to
// traversal): which shape tests, which triangle tests and which structures' traversals. Every
// query takes it as a template argument that defaults to all of it, which is what the CPU
// compiles (a CPU does not pay for code a scene never runs). A GPU pays for it in registers:
// the stream schedule's closest-hit and any-hit kernels come in variants compiled with only
// what a kind of scene needs (kernel/accel/trace_variants.h), each 8 to 25 registers smaller.
// A variant runs only scenes whose needs it holds, so its answers are those of the full code.
#pragma once
#include "kernel/base/features.h"
#include "kernel/scene/render_settings.h"

namespace tracer {

// The bits of a trace code. The shape tests are the shapes' FeatureBit values
// (kFeatureSphere, Plane, Triangle, Quad).
constexpr uint32_t kTraceShapes = kFeatureSphere | kFeaturePlane | kFeatureTriangle | kFeatureQuad;
// The triangle tests (RenderSettings::triangle_test).
constexpr uint32_t kTraceWatertight = 1u << 16;
constexpr uint32_t kTraceMollerTrumbore = 1u << 17;
// Cut-outs (kernel/accel/alpha_test.h): a code without it keeps every hit.
constexpr uint32_t kTraceAlpha = 1u << 18;
// The traversals (RenderSettings::accel): bvh and lbvh share one, as do the two kd-trees.
constexpr uint32_t kTraceBruteForce = 1u << 20;
constexpr uint32_t kTraceBvh = 1u << 21;
constexpr uint32_t kTraceKdtree = 1u << 22;
constexpr uint32_t kTraceGrid = 1u << 23;
// bvh's 8-wide tree (kernel/accel/traverse_wide_bvh.h), walked where the scene's view holds one.
constexpr uint32_t kTraceWideBvh = 1u << 24;
// The binary tree's pair records (kernel/accel/traverse_bvh_pairs.h), walked where the view
// holds them (a GPU upload of a scene of triangles: render/device_bvh.h); kTraceBvh is the
// walk of its nodes, which a scene without records needs.
constexpr uint32_t kTraceBvhPairs = 1u << 25;
constexpr uint32_t kTraceAll = 0xffffffffu;

// The traversal bit of a structure; `wide_tree`: bvh's 8-wide tree is the one walked;
// `pair_records`: the binary tree's pair records are (bvh and lbvh).
TRACER_HD constexpr uint32_t trace_accel_bit(AccelKind accel, bool wide_tree = false, bool pair_records = false) {
  switch (accel) {
    case AccelKind::None: return kTraceBruteForce;
    case AccelKind::Bvh: return wide_tree ? kTraceWideBvh : pair_records ? kTraceBvhPairs : kTraceBvh;
    case AccelKind::Lbvh: return pair_records ? kTraceBvhPairs : kTraceBvh;
    case AccelKind::Kdtree:
    case AccelKind::KdtreeMedian: return kTraceKdtree;
    case AccelKind::Grid: return kTraceGrid;
  }
  return kTraceAll;
}

// The triangle-test bit of a setting.
TRACER_HD constexpr uint32_t trace_triangle_test_bit(TriangleTest test) {
  return test == TriangleTest::Watertight ? kTraceWatertight : kTraceMollerTrumbore;
}

// Whether code `bits` is in kCode: a query compiled without it skips it.
template <uint32_t kCode>
TRACER_HD constexpr bool traces(uint32_t bits) {
  return (kCode & bits) != 0;
}

// Whether kCode is the full code (every shape, test and structure: the CPU's and the
// megakernels'), with or without the alpha test; a variant holds one structure.
template <uint32_t kCode>
TRACER_HD constexpr bool is_full_code() {
  return (kCode | kTraceAlpha) == kTraceAll;
}

// The full code of a kernel compiled for the feature mask kFeatures: without the alpha test
// where kFeatures has no cut-outs.
template <uint32_t kFeatures>
TRACER_HD constexpr uint32_t full_trace_code() {
  return (kFeatures & kFeatureAlpha) != 0u ? kTraceAll : kTraceAll & ~kTraceAlpha;
}

// Whether code kCode tests triangles watertight under `test` (else Moller-Trumbore).
template <uint32_t kCode>
TRACER_HD constexpr bool tests_watertight(TriangleTest test) {
  return traces<kCode>(kTraceWatertight) && (!traces<kCode>(kTraceMollerTrumbore) || test == TriangleTest::Watertight);
}

// Whether code kCode walks bvh's 8-wide tree where the view holds one. The GPU's full code
// does not (its stack frame stays the binary walk's): there the wide tree runs in its variant.
template <uint32_t kCode>
TRACER_HD constexpr bool walks_wide_bvh() {
#if defined(__CUDA_ARCH__)
  return !is_full_code<kCode>() && traces<kCode>(kTraceWideBvh);
#else
  return traces<kCode>(kTraceWideBvh);
#endif
}

// Whether code kCode walks the binary tree's pair records (kernel/accel/bvh_pair_node.h)
// where the view holds them, which it does only for scenes whose bounded primitives are all
// triangles: the full code and bvh_triangles (the wide tree's variant keeps the node walk, as
// its device holds no records).
template <uint32_t kCode>
TRACER_HD constexpr bool walks_bvh_pairs() {
  return traces<kCode>(kTraceBvhPairs) && traces<kCode>(kFeatureTriangle);
}

// The code that traces a scene: the shapes it holds (its FeatureBit mask), the triangle test
// its settings name when it holds triangles, and its structure's traversal (`wide_tree`: its
// view holds bvh's 8-wide tree; `pair_records`: the binary tree's pair records).
TRACER_HD constexpr uint32_t trace_code_needed(uint32_t features, AccelKind accel, TriangleTest test,
                                               bool wide_tree = false, bool pair_records = false) {
  const uint32_t shapes = features & kTraceShapes;
  return shapes | ((shapes & kFeatureTriangle) != 0 ? trace_triangle_test_bit(test) : 0u) |
         ((features & kFeatureAlpha) != 0 ? kTraceAlpha : 0u) | trace_accel_bit(accel, wide_tree, pair_records);
}

}  // namespace tracer
