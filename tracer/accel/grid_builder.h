// The uniform grid (kernel/accel/grid.h): grid_resolution cells along the longest axis, the
// others in proportion, or, when it is 0, about three cells per primitive spread by the
// box's shape (cells per axis = extent x cbrt(3 N / volume)), capped at 2^24 cells.
#pragma once
#include "accel/bounds.h"

namespace tracer {

void build_grid(Scene& scene, const std::vector<BuildItem>& items);

}  // namespace tracer
