#include "accel/lbvh_builder.h"

#include <omp.h>

#include "accel/lbvh_build.h"

namespace tracer {

std::vector<BvhNode> build_lbvh(std::vector<BuildItem>& items) {
  LbvhInput in;
  for (const BuildItem& it : items) {
    in.boxes.push_back({it.bounds.lo, it.bounds.hi});
    in.centroids.push_back(it.centroid);
    in.ids.push_back(it.id);
  }
  LbvhTree tree = build_lbvh_tree(in, [](size_t count, const auto& fn) {
#pragma omp parallel for
    for (int64_t i = 0; i < static_cast<int64_t>(count); ++i) fn(static_cast<size_t>(i));
  });
  std::vector<BuildItem> sorted;
  sorted.reserve(items.size());
  for (uint32_t k : tree.order) sorted.push_back(items[k]);
  items.swap(sorted);
  return std::move(tree.nodes);
}

}  // namespace tracer
