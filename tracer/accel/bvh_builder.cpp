#include "accel/bvh_builder.h"

#include <algorithm>

namespace tracer {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;
constexpr int kMaxBuildDepth = 60;       // traversal stacks hold 64 entries
constexpr uint32_t kTaskItems = 1u << 15;  // ranges at least this large build their halves as OpenMP tasks

int bin_of(float c, float lo, float extent) {
  const int b = static_cast<int>(static_cast<float>(kBins) * ((c - lo) / extent));
  return std::clamp(b, 0, kBins - 1);
}

struct Split {
  int axis = -1;  // -1: no axis separates the centroids
  int bin = 0;    // items in bins below `bin` go left
  float cost = kInfinity;
};

class BvhBuilder {
 public:
  explicit BvhBuilder(std::vector<BuildItem>& items) : items_(items) {}

  // The subtree over items [begin, end) with its root at index 0 and its interior nodes'
  // `first` relative to it: the node order of a depth-first build that appends both
  // children before descending into the first, whichever thread built which part.
  std::vector<BvhNode> build(uint32_t begin, uint32_t end, int depth) {
    std::vector<BvhNode> nodes(1);
    if (end - begin < kTaskItems) {
      build_node(nodes, 0, begin, end, depth);
      return nodes;
    }
    uint32_t mid;
    if (!split_or_leaf(nodes[0], begin, end, depth, mid)) return nodes;
    std::vector<BvhNode> left;
#pragma omp task shared(left) firstprivate(begin, mid, depth)
    left = build(begin, mid, depth + 1);
    std::vector<BvhNode> right = build(mid, end, depth + 1);
#pragma omp taskwait
    return splice(nodes[0], left, right);
  }

 private:
  void build_node(std::vector<BvhNode>& nodes, uint32_t node, uint32_t begin, uint32_t end, int depth) {
    uint32_t mid;
    if (!split_or_leaf(nodes[node], begin, end, depth, mid)) return;
    const uint32_t left = static_cast<uint32_t>(nodes.size());
    nodes.push_back({});
    nodes.push_back({});
    nodes[node].first = left;
    nodes[node].count = 0;
    build_node(nodes, left, begin, mid, depth + 1);
    build_node(nodes, left + 1, mid, end, depth + 1);
  }

  // Sets the node's box; makes it a leaf (returns false) or partitions its items at `mid`.
  bool split_or_leaf(BvhNode& node, uint32_t begin, uint32_t end, int depth, uint32_t& mid) {
    Bounds bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(items_[i].bounds);
      centroids.grow(items_[i].centroid);
    }
    node.lo = bounds.lo;
    node.hi = bounds.hi;
    node.first = begin;
    node.count = end - begin;
    const uint32_t count = end - begin;
    if (count <= kMaxLeafSize || depth >= kMaxBuildDepth) return false;
    const Split split = best_split(begin, end, centroids);
    if (split.axis < 0) {
      // All centroids coincide: split the list in half so the build always progresses.
      mid = begin + count / 2;
      return true;
    }
    const float leaf_cost = bounds.surface_area() * count;
    // Traversal step costs about as much as one primitive test (a cost of 1 per node).
    if (count <= 2 * kMaxLeafSize && split.cost + bounds.surface_area() >= leaf_cost) return false;
    const float lo = centroids.lo[split.axis], extent = centroids.hi[split.axis] - lo;
    const auto it = std::partition(items_.begin() + begin, items_.begin() + end, [&](const BuildItem& item) {
      return bin_of(item.centroid[split.axis], lo, extent) < split.bin;
    });
    mid = static_cast<uint32_t>(it - items_.begin());
    return true;
  }

  // The SAH cost of splitting at every bin boundary on every axis, binned in one pass.
  Split best_split(uint32_t begin, uint32_t end, const Bounds& centroids) const {
    Bounds bin_bounds[3][kBins];
    uint32_t bin_count[3][kBins] = {};
    float lo[3], extent[3];
    bool usable[3];
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = centroids.lo[axis];
      extent[axis] = centroids.hi[axis] - lo[axis];
      usable[axis] = extent[axis] > 0.0f;
    }
    for (uint32_t i = begin; i < end; ++i) {
      const BuildItem& item = items_[i];
      for (int axis = 0; axis < 3; ++axis) {
        if (!usable[axis]) continue;
        const int b = bin_of(item.centroid[axis], lo[axis], extent[axis]);
        bin_bounds[axis][b].grow(item.bounds);
        ++bin_count[axis][b];
      }
    }
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!usable[axis]) continue;
      float right_area[kBins];
      uint32_t right_count[kBins];
      Bounds acc;
      uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(bin_bounds[axis][b]);
        n += bin_count[axis][b];
        right_area[b] = acc.surface_area();
        right_count[b] = n;
      }
      acc = Bounds{};
      n = 0;
      for (int split = 1; split < kBins; ++split) {
        acc.grow(bin_bounds[axis][split - 1]);
        n += bin_count[axis][split - 1];
        if (n == 0 || right_count[split] == 0) continue;
        const float cost = acc.surface_area() * n + right_area[split] * right_count[split];
        if (cost < best.cost) best = {axis, split, cost};
      }
    }
    return best;
  }

  // [root, left root, right root, left's other nodes, right's other nodes], indices shifted.
  static std::vector<BvhNode> splice(BvhNode root, const std::vector<BvhNode>& left,
                                     const std::vector<BvhNode>& right) {
    const uint32_t left_shift = 2, right_shift = static_cast<uint32_t>(left.size()) + 1;
    const auto shifted = [](BvhNode n, uint32_t shift) {
      if (n.count == 0) n.first += shift;
      return n;
    };
    std::vector<BvhNode> nodes;
    nodes.reserve(1 + left.size() + right.size());
    root.first = 1;
    root.count = 0;
    nodes.push_back(root);
    nodes.push_back(shifted(left[0], left_shift));
    nodes.push_back(shifted(right[0], right_shift));
    for (size_t i = 1; i < left.size(); ++i) nodes.push_back(shifted(left[i], left_shift));
    for (size_t i = 1; i < right.size(); ++i) nodes.push_back(shifted(right[i], right_shift));
    return nodes;
  }

  std::vector<BuildItem>& items_;
};

}  // namespace

std::vector<BvhNode> build_sah_bvh(std::vector<BuildItem>& items) {
  if (items.empty()) return {};
  std::vector<BvhNode> nodes;
  BvhBuilder builder(items);
  const uint32_t n = static_cast<uint32_t>(items.size());
#pragma omp parallel if (n >= kTaskItems)
#pragma omp single
  nodes = builder.build(0, n, 0);
  return nodes;
}

}  // namespace tracer
