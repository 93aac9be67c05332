// Uniform-grid traversal by the 3D-DDA of Amanatides and Woo ("A Fast Voxel Traversal
// Algorithm for Ray Tracing", 1987): step from cell to cell across the nearest boundary.
// Each boundary's t is computed afresh from its coordinate (not accumulated), primitives
// sit in every cell their padded bounds overlap, and the walk stops early only when the
// best hit lies before the cell's exit minus the pad (docs/determinism.md rule 4).
#pragma once
#include "kernel/accel/primitive_hit.h"
#include "kernel/base/float_to_int.h"

namespace tracer {

template <uint32_t kCode = kTraceAll>
TRACER_HD void traverse_grid(const SceneView& scene, const Ray& ray, const RayShear& shear, Hit& best, bool any) {
  const GridInfo& g = scene.grid;
  if (g.n[0] == 0) return;
  const Vec3 inv = inverse_direction(ray.dir);
  float t_enter;
  if (!ray_box(g.lo, g.hi, ray.origin, inv, 0.0f, best.t, t_enter)) return;
  int cell[3];
  for (int a = 0; a < 3; ++a) {
    const float p = ray.origin[a] + ray.dir[a] * t_enter;
    const int c = trunc_to_int32((p - g.lo[a]) / g.cell[a]);
    cell[a] = c < 0 ? 0 : (c >= static_cast<int>(g.n[a]) ? static_cast<int>(g.n[a]) - 1 : c);
  }
  for (;;) {
    const uint32_t c = static_cast<uint32_t>(cell[0]) +
                       g.n[0] * (static_cast<uint32_t>(cell[1]) + g.n[1] * static_cast<uint32_t>(cell[2]));
    for (uint32_t i = scene.grid_cell_start[c]; i < scene.grid_cell_start[c + 1]; ++i) {
      test_primitive<leaf_trace_code<kCode>()>(scene, scene.grid_prims[i], ray, shear, best);
      if (any && best.prim != kNoHit) return;
    }
    // The boundary crossed first, and the t at which it is crossed.
    int axis = -1;
    float t_exit = kInfinity;
    for (int a = 0; a < 3; ++a) {
      if (!(ray.dir[a] > 0.0f) && !(ray.dir[a] < 0.0f)) continue;  // parallel to the axis's boundaries
      const float boundary = g.lo[a] + static_cast<float>(cell[a] + (ray.dir[a] > 0.0f ? 1 : 0)) * g.cell[a];
      const float t = (boundary - ray.origin[a]) * inv[a];
      if (t < t_exit) t_exit = t, axis = a;
    }
    if (axis < 0 || best.t < t_exit - g.pad) return;
    cell[axis] += ray.dir[axis] > 0.0f ? 1 : -1;
    if (cell[axis] < 0 || cell[axis] >= static_cast<int>(g.n[axis])) return;
  }
}

}  // namespace tracer
