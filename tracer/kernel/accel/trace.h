// Closest-hit and any-hit queries, dispatched on the acceleration structure with a switch.
// Every structure returns the same hit, bit for bit: the closest hit is the minimum of
// (t, primitive id), and no structure prunes a candidate that could beat it (DESIGN.md rule 4).
#pragma once
#include "kernel/accel/traverse_bvh.h"
#include "kernel/accel/traverse_grid.h"
#include "kernel/accel/traverse_kdtree.h"
#include "kernel/accel/traverse_wide_bvh.h"

// A hook on every query, empty except where the path-cost benchmark records the rays a
// render casts (tracer/bench/ray_recorder.cpp) to replay them through traversal alone.
#ifndef TRACER_TRACE_HOOK
#define TRACER_TRACE_HOOK(ray, tmax, any)
#endif

namespace tracer {

// Tests the planes, then the bounded primitives through the scene's structure.
TRACER_HD void trace_into(const SceneView& scene, const Ray& ray, Hit& best, bool any) {
  const RayShear shear = make_ray_shear(ray.dir);
  for (uint32_t i = 0; i < scene.unbounded_count; ++i) {
    test_primitive(scene, scene.unbounded[i], ray, shear, best);
    if (any && best.prim != kNoHit) return;
  }
  switch (scene.settings.accel) {
    case AccelKind::None:
      for (uint32_t i = 0; i < scene.bounded_count; ++i) {
        test_primitive(scene, scene.bounded[i], ray, shear, best);
        if (any && best.prim != kNoHit) return;
      }
      break;
    case AccelKind::Bvh:
#if !defined(__CUDA_ARCH__)  // the GPU walks the binary tree until a GPU run shows the wide one is faster there
      if (scene.wide_node_count != 0) {
        traverse_wide_bvh(scene, ray, shear, best, any);
        break;
      }
#endif
      traverse_bvh(scene, ray, shear, best, any);
      break;
    case AccelKind::Lbvh: traverse_bvh(scene, ray, shear, best, any); break;
    case AccelKind::Kdtree:
    case AccelKind::KdtreeMedian: traverse_kdtree(scene, ray, shear, best, any); break;
    case AccelKind::Grid: traverse_grid(scene, ray, shear, best, any); break;
  }
}

// Closest hit with t in (0, tmax].
TRACER_HD Hit trace_closest(const SceneView& scene, const Ray& ray, float tmax) {
  TRACER_TRACE_HOOK(ray, tmax, false);
  Hit best = {tmax, kNoHit, 0.0f, 0.0f};
  trace_into(scene, ray, best, false);
  return best;
}

// Any hit with t in (0, tmax): the shadow-ray query. The answer is a property of the set
// of primitives, so the order of visits cannot change it.
TRACER_HD bool trace_any(const SceneView& scene, const Ray& ray, float tmax) {
  TRACER_TRACE_HOOK(ray, tmax, true);
  // Ask for t <= the float just below tmax: a hit exactly at the light does not occlude.
  Hit probe = {float_of_bits(bits_of(tmax) - 1u), kNoHit, 0.0f, 0.0f};
  trace_into(scene, ray, probe, true);
  return probe.prim != kNoHit;
}

}  // namespace tracer
