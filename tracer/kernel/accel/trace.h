// Closest-hit and any-hit queries, dispatched on the acceleration structure with a switch.
// Every structure returns the same hit, bit for bit: the closest hit is the minimum of
// (t, primitive id), and no structure prunes a candidate that could beat it (docs/determinism.md rule 4).
#pragma once
#include "kernel/accel/traverse_bvh.h"
#include "kernel/accel/traverse_bvh_pairs.h"
#include "kernel/accel/traverse_grid.h"
#include "kernel/accel/traverse_kdtree.h"
#include "kernel/accel/traverse_wide_bvh.h"

// A hook on every query, empty except where the path-cost benchmark records the rays a
// render casts (tracer/bench/ray_recorder.cpp) to replay them through traversal alone.
#ifndef TRACER_TRACE_HOOK
#define TRACER_TRACE_HOOK(ray, tmax, any)
#endif

namespace tracer {

// Tests the planes, then the bounded primitives through the scene's structure. A structure
// outside kCode (trace_code.h) is never the one of the scenes that run it.
template <uint32_t kCode = kTraceAll>
TRACER_HD void trace_into(const SceneView& scene, const Ray& ray, Hit& best, bool any) {
  const RayShear shear = make_ray_shear(ray.dir);
  for (uint32_t i = 0; i < scene.unbounded_count; ++i) {
    test_primitive<kCode>(scene, scene.unbounded[i], ray, shear, best);
    if (any && best.prim != kNoHit) return;
  }
  switch (scene.settings.accel) {
    case AccelKind::None:
      if (!traces<kCode>(kTraceBruteForce)) break;
      for (uint32_t i = 0; i < scene.bounded_count; ++i) {
        test_primitive<leaf_trace_code<kCode>()>(scene, scene.bounded[i], ray, shear, best);
        if (any && best.prim != kNoHit) return;
      }
      break;
    case AccelKind::Bvh:  // the 8-wide tree, or the binary one where it is deeper than the walk's stack
      if (walks_wide_bvh<kCode>() && scene.wide_node_count != 0 &&
          traverse_wide_bvh<kCode>(scene, ray, shear, best, any))
        break;
      [[fallthrough]];
    case AccelKind::Lbvh:
      if (walks_bvh_pairs<kCode>() && scene.bvh_pair_count != 0)
        traverse_bvh_pairs<kCode>(scene, ray, shear, best, any);
      else if (traces<kCode>(kTraceBvh))
        traverse_bvh<kCode>(scene, ray, shear, best, any);
      break;
    case AccelKind::Kdtree:
    case AccelKind::KdtreeMedian:
      if (traces<kCode>(kTraceKdtree)) traverse_kdtree<kCode>(scene, ray, shear, best, any);
      break;
    case AccelKind::Grid:
      if (traces<kCode>(kTraceGrid)) traverse_grid<kCode>(scene, ray, shear, best, any);
      break;
  }
}

// The one query. With `any`, whether anything lies at t in (0, tmax), the shadow ray's
// question: t <= the float just below tmax, so a hit exactly at the light does not occlude;
// the answer is a property of the set of primitives, so the order of visits cannot change it.
// Without, the closest hit with t in (0, tmax]. A ray whose origin or direction is not finite
// (a material's arithmetic gone to NaN) hits nothing on any structure: the box tests' min and
// max drop a NaN, so a walk would otherwise enter every child, empty ones too.
template <uint32_t kCode = kTraceAll>
TRACER_HD Hit trace_query(const SceneView& scene, const Ray& ray, float tmax, bool any) {
  TRACER_TRACE_HOOK(ray, tmax, any);
  Hit best = {any ? float_of_bits(bits_of(tmax) - 1u) : tmax, kNoHit, 0.0f, 0.0f};
  if (!is_finite(ray.origin) || !is_finite(ray.dir)) return best;
  trace_into<kCode>(scene, ray, best, any);
  return best;
}

// Closest hit with t in (0, tmax].
template <uint32_t kCode = kTraceAll>
TRACER_HD Hit trace_closest(const SceneView& scene, const Ray& ray, float tmax) {
  return trace_query<kCode>(scene, ray, tmax, false);
}

// Any hit with t in (0, tmax).
template <uint32_t kCode = kTraceAll>
TRACER_HD bool trace_any(const SceneView& scene, const Ray& ray, float tmax) {
  return trace_query<kCode>(scene, ray, tmax, true).prim != kNoHit;
}

}  // namespace tracer
