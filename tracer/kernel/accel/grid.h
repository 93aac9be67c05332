// A uniform grid over the bounded primitives (kernel/accel/traverse_grid.h): cell (x, y, z) holds
// grid_prims[cell_start[c] .. cell_start[c + 1]) with c = x + n.x (y + n.y z). Primitives
// are listed in every cell their bounds, widened by `pad`, overlap.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

struct GridInfo {
  Vec3 lo, hi;    // the grid's box
  Vec3 cell;      // cell size per axis
  uint32_t n[3];  // cells per axis; 0 when there is no grid
  float pad;      // world-space widening of primitive bounds and shrinking of cell exits
};

}  // namespace tracer
