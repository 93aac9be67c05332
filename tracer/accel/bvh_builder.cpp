#include "accel/bvh_builder.h"

#include <algorithm>

namespace tracer {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;
constexpr int kMaxBuildDepth = 60;  // traversal stacks hold 64 entries

class BvhBuilder {
 public:
  explicit BvhBuilder(std::vector<BuildItem>& items) : items_(items) {}

  std::vector<BvhNode> build() {
    nodes_.push_back({});
    build_node(0, 0, static_cast<uint32_t>(items_.size()), 0);
    return std::move(nodes_);
  }

 private:
  void make_leaf(uint32_t node, uint32_t begin, uint32_t end) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
  }

  void build_node(uint32_t node, uint32_t begin, uint32_t end, int depth) {
    Bounds bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(items_[i].bounds);
      centroids.grow(items_[i].centroid);
    }
    nodes_[node].lo = bounds.lo;
    nodes_[node].hi = bounds.hi;
    const uint32_t count = end - begin;
    if (count <= kMaxLeafSize || depth >= kMaxBuildDepth) return make_leaf(node, begin, end);

    // Evaluate the SAH cost of splitting at every bin boundary on every axis.
    float best_cost = kInfinity;
    int best_axis = -1, best_split = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
      if (!(extent > 0.0f)) continue;
      Bounds bin_bounds[kBins];
      uint32_t bin_count[kBins] = {};
      for (uint32_t i = begin; i < end; ++i) {
        const int b = bin_of(items_[i].centroid[axis], lo, extent);
        bin_bounds[b].grow(items_[i].bounds);
        ++bin_count[b];
      }
      float right_area[kBins];
      uint32_t right_count[kBins];
      Bounds acc;
      uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(bin_bounds[b]);
        n += bin_count[b];
        right_area[b] = acc.surface_area();
        right_count[b] = n;
      }
      acc = Bounds{};
      n = 0;
      for (int split = 1; split < kBins; ++split) {
        acc.grow(bin_bounds[split - 1]);
        n += bin_count[split - 1];
        if (n == 0 || right_count[split] == 0) continue;
        const float cost = acc.surface_area() * n + right_area[split] * right_count[split];
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_split = split;
        }
      }
    }

    uint32_t mid;
    if (best_axis < 0) {
      // All centroids coincide: split the list in half so the build always progresses.
      mid = begin + count / 2;
    } else {
      const float leaf_cost = bounds.surface_area() * count;
      // Traversal step costs about as much as one primitive test (a cost of 1 per node).
      if (count <= 2 * kMaxLeafSize && best_cost + bounds.surface_area() >= leaf_cost)
        return make_leaf(node, begin, end);
      const float lo = centroids.lo[best_axis], extent = centroids.hi[best_axis] - lo;
      const auto it = std::partition(items_.begin() + begin, items_.begin() + end, [&](const BuildItem& it) {
        return bin_of(it.centroid[best_axis], lo, extent) < best_split;
      });
      mid = static_cast<uint32_t>(it - items_.begin());
    }
    const uint32_t left = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[node].first = left;
    nodes_[node].count = 0;
    build_node(left, begin, mid, depth + 1);
    build_node(left + 1, mid, end, depth + 1);
  }

  static int bin_of(float c, float lo, float extent) {
    const int b = static_cast<int>(static_cast<float>(kBins) * ((c - lo) / extent));
    return std::clamp(b, 0, kBins - 1);
  }

  std::vector<BuildItem>& items_;
  std::vector<BvhNode> nodes_;
};

}  // namespace

std::vector<BvhNode> build_sah_bvh(std::vector<BuildItem>& items) {
  if (items.empty()) return {};
  return BvhBuilder(items).build();
}

}  // namespace tracer
