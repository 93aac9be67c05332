#include "accel/acceleration.h"

#include <algorithm>

#include "accel/bvh_builder.h"
#include "accel/grid_builder.h"
#include "accel/huge_pages.h"
#include "accel/kdtree_builder.h"
#include "accel/lbvh_builder.h"
#include "options/enum_names.h"

namespace tracer {

float structure_pad(Vec3 lo, Vec3 hi) {
  const float magnitude = max_of(max_component(max_of(lo, -lo)), max_component(max_of(hi, -hi)));
  return max_of(magnitude, max_component(hi - lo)) * 0x1p-18f + 0x1p-100f;
}

namespace {

// An item per bounded primitive, in primitive order (planes have no box): fixed chunks of
// primitives count theirs, then each fills its items from its offset, so the items are the
// same for any thread count.
std::vector<BuildItem> bounded_items(std::span<const Primitive> primitives) {
  constexpr uint32_t kChunk = 1u << 16;
  const uint32_t n = static_cast<uint32_t>(primitives.size()), chunks = (n + kChunk - 1) / kChunk;
  std::vector<uint32_t> offset(size_t{chunks} + 1, 0);
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (int64_t c = 0; c < static_cast<int64_t>(chunks); ++c) {
    const uint32_t begin = static_cast<uint32_t>(c) * kChunk, end = std::min(n, begin + kChunk);
    uint32_t bounded = 0;
    for (uint32_t id = begin; id < end; ++id) bounded += primitives[id].kind != ShapeKind::Plane;
    offset[static_cast<size_t>(c) + 1] = bounded;
  }
  for (uint32_t c = 0; c < chunks; ++c) offset[c + 1] += offset[c];
  std::vector<BuildItem> items;
  reserve_on_huge_pages(items, offset[chunks]);
  items.resize(offset[chunks]);
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (int64_t c = 0; c < static_cast<int64_t>(chunks); ++c) {
    const uint32_t begin = static_cast<uint32_t>(c) * kChunk, end = std::min(n, begin + kChunk);
    uint32_t k = offset[static_cast<size_t>(c)];
    for (uint32_t id = begin; id < end; ++id) {
      if (primitives[id].kind == ShapeKind::Plane) continue;
      const Bounds b = primitive_bounds(primitives[id]);
      items[k++] = {b, (b.lo + b.hi) * 0.5f, id};
    }
  }
  return items;
}

}  // namespace

Acceleration build_acceleration(AccelKind kind, std::span<const Primitive> primitives, uint32_t grid_resolution) {
  Acceleration a;
  if (kind == AccelKind::Bvh) {  // the SAH builder makes its own compact boxes of the primitives
    a.bvh_nodes = build_sah_bvh(primitives, a.bounded);
    a.wide = collapse_to_wide_bvh(a.bvh_nodes, a.bounded, primitives);
  } else {
    std::vector<BuildItem> items = bounded_items(primitives);
    switch (kind) {
      case AccelKind::Lbvh: a.bvh_nodes = build_lbvh(items); break;
      case AccelKind::Kdtree: a.kd = build_kdtree(items, KdSplit::Sah); break;
      case AccelKind::KdtreeMedian: a.kd = build_kdtree(items, KdSplit::Median); break;
      case AccelKind::Grid: a.grid = build_grid(items, grid_resolution); break;
      case AccelKind::Bvh:
      case AccelKind::None: break;
    }
    // These builders reorder `items` into the order their leaves index.
    reserve_on_huge_pages(a.bounded, items.size());
    for (const BuildItem& it : items) a.bounded.push_back(it.id);
  }
  if (a.bounded.size() < primitives.size())
    for (uint32_t id = 0; id < primitives.size(); ++id)
      if (primitives[id].kind == ShapeKind::Plane) a.unbounded.push_back(id);
  return a;
}

AccelSummary acceleration_summary(AccelKind kind, const Acceleration& a) {
  AccelSummary s;
  s.name = enum_name(kind);
  s.nodes = a.bvh_nodes.size() + a.kd.nodes.size();
  if (kind == AccelKind::Grid) s.cells = a.grid.cell_start.empty() ? 0 : a.grid.cell_start.size() - 1;
  return s;
}

size_t acceleration_bytes(const Acceleration& a) {
  return a.bvh_nodes.size() * sizeof(BvhNode) + a.bounded.size() * sizeof(uint32_t) +
         a.wide.nodes.size() * sizeof(WideBvhNode) + a.wide.blocks.size() * sizeof(TriangleBlock) +
         a.kd.nodes.size() * sizeof(KdNode) +
         (a.kd.prims.size() + a.grid.cell_start.size() + a.grid.prims.size()) * sizeof(uint32_t);
}

}  // namespace tracer
