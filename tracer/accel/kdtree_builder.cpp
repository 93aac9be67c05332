#include "accel/kdtree_builder.h"

#include <algorithm>
#include <cmath>

#include "accel/acceleration.h"

namespace tracer {
namespace {

constexpr int kBins = 32;
constexpr float kTraversalCost = 1.0f, kIntersectionCost = 1.5f, kEmptyBonus = 0.2f;

class KdBuilder {
 public:
  KdBuilder(KdTree& tree, const std::vector<BuildItem>& items, KdSplit split, float pad)
      : tree_(tree),
        items_(items),
        split_(split),
        pad_(pad),
        max_depth_(8 + static_cast<int>(1.3 * std::log2(std::max<size_t>(items.size(), 1)))) {}

  void build(const Bounds& box) {
    std::vector<uint32_t> all(items_.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    tree_.nodes.push_back({});
    build_node(0, box, all, 0);
  }

 private:
  float lo_of(uint32_t i, int axis) const { return items_[i].bounds.lo[axis] - pad_; }
  float hi_of(uint32_t i, int axis) const { return items_[i].bounds.hi[axis] + pad_; }

  void make_leaf(uint32_t node, const std::vector<uint32_t>& list) {
    tree_.nodes[node] = {kKdLeaf, static_cast<uint32_t>(tree_.prims.size()), static_cast<uint32_t>(list.size()), 0.0f};
    for (uint32_t i : list) tree_.prims.push_back(items_[i].id);
  }

  // The SAH's best split, or false when a leaf is cheaper.
  bool sah_split(const Bounds& box, const std::vector<uint32_t>& list, int& axis_out, float& split_out) const {
    const float area = box.surface_area();
    float best = kIntersectionCost * static_cast<float>(list.size());
    bool found = false;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = box.lo[axis], extent = box.hi[axis] - lo;
      if (!(extent > 0.0f)) continue;
      uint32_t starts[kBins] = {}, ends[kBins] = {};
      const auto bin = [&](float v) { return std::clamp(static_cast<int>((v - lo) / extent * kBins), 0, kBins - 1); };
      for (uint32_t i : list) ++starts[bin(lo_of(i, axis))], ++ends[bin(hi_of(i, axis))];
      uint32_t below = 0, above = static_cast<uint32_t>(list.size());
      for (int k = 1; k < kBins; ++k) {
        below += starts[k - 1];
        above -= ends[k - 1];
        const float split = lo + extent * static_cast<float>(k) / kBins;
        Bounds b = box, a = box;
        b.hi[axis] = split;
        a.lo[axis] = split;
        float cost =
            kTraversalCost + kIntersectionCost * (b.surface_area() / area * below + a.surface_area() / area * above);
        if (below == 0 || above == 0) cost *= 1.0f - kEmptyBonus;
        if (cost < best) best = cost, axis_out = axis, split_out = split, found = true;
      }
    }
    return found;
  }

  bool median_split(const Bounds& box, const std::vector<uint32_t>& list, int& axis_out, float& split_out) const {
    if (list.size() <= 4) return false;
    const Vec3 d = box.hi - box.lo;
    const int axis = d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
    std::vector<float> c;
    for (uint32_t i : list) c.push_back(items_[i].centroid[axis]);
    std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
    axis_out = axis;
    split_out = c[c.size() / 2];
    return split_out > box.lo[axis] && split_out < box.hi[axis];
  }

  void build_node(uint32_t node, const Bounds& box, const std::vector<uint32_t>& list, int depth) {
    int axis = 0;
    float split = 0.0f;
    const bool divide =
        depth < max_depth_ && list.size() > 2 &&
        (split_ == KdSplit::Sah ? sah_split(box, list, axis, split) : median_split(box, list, axis, split));
    std::vector<uint32_t> below, above;
    if (divide)
      for (uint32_t i : list) {
        if (lo_of(i, axis) <= split) below.push_back(i);
        if (hi_of(i, axis) >= split) above.push_back(i);
      }
    if (!divide || (below.size() == list.size() && above.size() == list.size())) return make_leaf(node, list);
    const uint32_t b = static_cast<uint32_t>(tree_.nodes.size());
    tree_.nodes.push_back({});
    tree_.nodes.push_back({});
    tree_.nodes[node] = {static_cast<uint32_t>(axis), b, b + 1, split};
    Bounds box_below = box, box_above = box;
    box_below.hi[axis] = split;
    box_above.lo[axis] = split;
    build_node(b, box_below, below, depth + 1);
    build_node(b + 1, box_above, above, depth + 1);
  }

  KdTree& tree_;
  const std::vector<BuildItem>& items_;
  KdSplit split_;
  float pad_;
  int max_depth_;
};

}  // namespace

KdTree build_kdtree(const std::vector<BuildItem>& items, KdSplit split) {
  KdTree tree;
  if (items.empty()) return tree;
  Bounds box;
  for (const BuildItem& it : items) box.grow(it.bounds);
  tree.pad = structure_pad(box.lo, box.hi);
  const Vec3 p = {tree.pad, tree.pad, tree.pad};
  tree.lo = box.lo - p;
  tree.hi = box.hi + p;
  KdBuilder(tree, items, split, tree.pad).build({tree.lo, tree.hi});
  return tree;
}

}  // namespace tracer
