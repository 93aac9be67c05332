#include "accel/grid_builder.h"

#include <algorithm>
#include <cmath>

#include "accel/acceleration.h"

namespace tracer {

UniformGrid build_grid(const std::vector<BuildItem>& items, uint32_t resolution) {
  UniformGrid grid;
  if (items.empty()) return grid;
  Bounds box;
  for (const BuildItem& it : items) box.grow(it.bounds);
  const float pad = structure_pad(box.lo, box.hi);
  const Vec3 p = {pad, pad, pad};
  box.lo = box.lo - p;
  box.hi = box.hi + p;
  const Vec3 extent = box.hi - box.lo;
  const double longest = max_component(extent);
  uint32_t n[3];
  const double density = std::cbrt(3.0 * items.size() / (double(extent.x) * extent.y * extent.z));
  for (int a = 0; a < 3; ++a) {
    const double cells = resolution > 0 ? resolution * extent[a] / longest : extent[a] * density;
    n[a] = static_cast<uint32_t>(std::clamp(std::lround(cells), 1l, 1024l));
  }
  while (uint64_t(n[0]) * n[1] * n[2] > (1u << 24))
    for (uint32_t& c : n) c = std::max(1u, c / 2);
  GridInfo& g = grid.info;
  g.lo = box.lo;
  g.hi = box.hi;
  g.cell = {extent.x / n[0], extent.y / n[1], extent.z / n[2]};
  g.n[0] = n[0], g.n[1] = n[1], g.n[2] = n[2];
  g.pad = pad;

  // Cell ranges of each primitive's padded bounds; then counts, prefix sums and the fill.
  const auto range = [&](const BuildItem& it, int a, int& first, int& last) {
    first = std::clamp(static_cast<int>(std::floor((it.bounds.lo[a] - pad - g.lo[a]) / g.cell[a])), 0, int(n[a]) - 1);
    last = std::clamp(static_cast<int>(std::floor((it.bounds.hi[a] + pad - g.lo[a]) / g.cell[a])), 0, int(n[a]) - 1);
  };
  const size_t cells = size_t(n[0]) * n[1] * n[2];
  grid.cell_start.assign(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (size_t c = 0; c < cells; ++c) grid.cell_start[c + 1] += grid.cell_start[c];
      grid.prims.resize(grid.cell_start[cells]);
    }
    std::vector<uint32_t> fill(pass == 1 ? grid.cell_start.begin() : grid.cell_start.end(), grid.cell_start.end());
    for (const BuildItem& it : items) {
      int lo[3], hi[3];
      for (int a = 0; a < 3; ++a) range(it, a, lo[a], hi[a]);
      for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
          for (int x = lo[0]; x <= hi[0]; ++x) {
            const size_t c = size_t(x) + n[0] * (size_t(y) + n[1] * size_t(z));
            if (pass == 0)
              ++grid.cell_start[c + 1];
            else
              grid.prims[fill[c]++] = it.id;
          }
    }
  }
  return grid;
}

}  // namespace tracer
