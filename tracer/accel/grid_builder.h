// The uniform grid (kernel/accel/grid.h): grid_resolution cells along the longest axis, the
// others in proportion, or, when it is 0, about three cells per primitive spread by the
// box's shape (cells per axis = extent x cbrt(3 N / volume)), capped at 2^24 cells.
#pragma once
#include "accel/bounds.h"
#include "kernel/accel/grid.h"

namespace tracer {

// The grid over `items`: its geometry, and per cell a range of grid_prims (cell_start has
// one entry per cell and a last one past the end).
struct UniformGrid {
  GridInfo info{};
  std::vector<uint32_t> cell_start, prims;
};
UniformGrid build_grid(const std::vector<BuildItem>& items, uint32_t resolution);

}  // namespace tracer
