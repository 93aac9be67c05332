#include "accel/wide_bvh_builder.h"

#include <algorithm>

#include "accel/bounds.h"
#include "accel/bvh_builder.h"  // kParallelBuildItems
#include "accel/huge_pages.h"
#include "kernel/scene/scene_view.h"  // kNoHit

namespace tracer {
namespace {

class WideBvhCollapser {
  struct Leaf {
    uint32_t block, first, count;  // its first block; its primitives leaf_order_[first .. first + count)
  };

 public:
  WideBvhCollapser(std::span<const BvhNode> binary, std::span<const uint32_t> leaf_order,
                   std::span<const Primitive> primitives)
      : binary_(binary), leaf_order_(leaf_order), primitives_(primitives) {}

  WideBvh collapse() {
    // Sized once: a wide node per collapsed interior binary node at most, and each leaf's blocks.
    size_t interior = 0, blocks = 0;
    for (const BvhNode& n : binary_) n.count == 0 ? ++interior : blocks += (n.count + kBlockLanes - 1) / kBlockLanes;
    reserve_on_huge_pages(wide_.nodes, interior + 1);
    reserve_on_huge_pages(wide_.blocks, blocks);
    leaves_.reserve(binary_.size() - interior);
    subtree_items_.resize(binary_.size());
    for (size_t i = binary_.size(); i-- > 0;)  // children follow their parent in the array
      subtree_items_[i] = binary_[i].count != 0
                              ? binary_[i].count
                              : subtree_items_[binary_[i].first] + subtree_items_[binary_[i].first + 1];
    const BvhNode& root = binary_[0];
    if (root.count > 0) {  // a single leaf: one node with one child
      wide_.nodes.push_back(empty_node());
      set_child(0, 0, 0);
    } else {
      collapse_node(0);
    }
    fill_blocks();
    return std::move(wide_);
  }

 private:
  static float area(const BvhNode& n) {
    Bounds b;
    b.lo = n.lo;
    b.hi = n.hi;
    return b.surface_area();
  }

  static WideBvhNode empty_node() {
    WideBvhNode n{};
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < kWideBvhWidth; ++i) n.lo[a][i] = kInfinity, n.hi[a][i] = -kInfinity;
    return n;
  }

  // Makes the wide node for binary interior node `b`; returns its index.
  uint32_t collapse_node(uint32_t b) {
    uint32_t children[kWideBvhWidth] = {binary_[b].first, binary_[b].first + 1};
    float areas[kWideBvhWidth];  // an interior child's area; -1 for a leaf, never expanded
    const auto area_of = [&](uint32_t c) { return binary_[c].count == 0 ? area(binary_[c]) : -1.0f; };
    areas[0] = area_of(children[0]), areas[1] = area_of(children[1]);
    int count = 2;
    while (count < kWideBvhWidth) {
      int widest = -1;
      for (int i = 0; i < count; ++i)
        if (areas[i] >= 0.0f && (widest < 0 || areas[i] > areas[widest])) widest = i;
      if (widest < 0) break;
      const uint32_t first = binary_[children[widest]].first;
      children[widest] = first, areas[widest] = area_of(first);
      children[count] = first + 1, areas[count] = area_of(first + 1);
      ++count;
    }
    const uint32_t index = static_cast<uint32_t>(wide_.nodes.size());
    wide_.nodes.push_back(empty_node());
    for (int i = 0; i < count; ++i) set_child(index, i, children[i]);
    for (int i = 0; i < count; ++i) {
      if (is_leaf(children[i])) continue;
      const uint32_t subtree = collapse_node(children[i]);  // grows wide_.nodes
      wide_.nodes[index].child[i] = subtree;
    }
    return index;
  }

  // A subtree of at most two blocks' worth of items becomes one leaf of its items (contiguous
  // in leaf order) rather than a wide node with two or three children: one box test fewer.
  bool is_leaf(uint32_t b) const { return binary_[b].count != 0 || subtree_items_[b] <= 2 * kBlockLanes; }

  // The first item, in leaf order, of binary node `b`'s subtree.
  uint32_t first_item(uint32_t b) const {
    while (binary_[b].count == 0) b = binary_[b].first;
    return binary_[b].first;
  }

  void set_child(uint32_t node, int slot, uint32_t b) {
    WideBvhNode& n = wide_.nodes[node];
    const BvhNode& child = binary_[b];
    for (int a = 0; a < 3; ++a) n.lo[a][slot] = child.lo[a], n.hi[a][slot] = child.hi[a];
    if (!is_leaf(b)) return;  // interior: child[slot] is set once the subtree exists
    const uint32_t items = subtree_items_[b];
    n.child[slot] = block_count_;
    n.leaf_blocks[slot] = (items + kBlockLanes - 1) / kBlockLanes;
    leaves_.push_back({block_count_, first_item(b), items});
    block_count_ += n.leaf_blocks[slot];
  }

  // Every leaf's blocks, in parallel: each leaf owns its blocks. (The GPU runner, which
  // collapses a bundle's tree for its rays table, is built without OpenMP.)
  void fill_blocks() {
    wide_.blocks.resize(block_count_);
#if defined(_OPENMP)
#pragma omp parallel for schedule(static, 4096) if (leaf_order_.size() >= kParallelBuildItems)
#endif
    for (int64_t i = 0; i < static_cast<int64_t>(leaves_.size()); ++i) {
      const Leaf& leaf = leaves_[static_cast<size_t>(i)];
      for (uint32_t k = 0; k < leaf.count; ++k) add_to_block(leaf, k, leaf_order_[leaf.first + k]);
    }
  }

  // The k-th primitive of a leaf goes to lane k % 4 of the leaf's (k / 4)-th block.
  void add_to_block(const Leaf& leaf, uint32_t k, uint32_t id) {
    const int lane = static_cast<int>(k % kBlockLanes);
    TriangleBlock& block = wide_.blocks[leaf.block + k / kBlockLanes];
    if (lane == 0) {
      block = TriangleBlock{};
      for (uint32_t& i : block.id) i = kNoHit;
    }
    block.id[lane] = id;
    const Primitive& p = primitives_[id];
    if (p.kind != ShapeKind::Triangle) {
      block.other_lanes |= 1u << lane;
      return;
    }
    block.triangle_lanes |= 1u << lane;
    const Vec3 corners[3] = {p.a, p.b, p.c};
    for (int v = 0; v < 3; ++v)
      for (int a = 0; a < 3; ++a) block.v[v][a][lane] = corners[v][a];
  }

  std::span<const BvhNode> binary_;
  std::span<const uint32_t> leaf_order_;
  std::span<const Primitive> primitives_;
  std::vector<uint32_t> subtree_items_;  // per binary node: the items below it
  std::vector<Leaf> leaves_;
  uint32_t block_count_ = 0;
  WideBvh wide_;
};

}  // namespace

WideBvh collapse_to_wide_bvh(std::span<const BvhNode> binary, std::span<const uint32_t> leaf_order,
                             std::span<const Primitive> primitives) {
  if (binary.empty()) return {};
  return WideBvhCollapser(binary, leaf_order, primitives).collapse();
}

uint32_t wide_bvh_stack_need(std::span<const WideBvhNode> nodes) {
  // A node's children follow it in the array (collapse_node makes a parent before its subtrees).
  std::vector<uint32_t> need(nodes.size(), 0);
  for (size_t i = nodes.size(); i-- > 0;) {
    const WideBvhNode& n = nodes[i];
    uint32_t children = 0, deepest = 0;
    for (int c = 0; c < kWideBvhWidth; ++c) {
      if (n.lo[0][c] > n.hi[0][c]) continue;  // an unused slot
      ++children;
      if (n.leaf_blocks[c] == 0) deepest = std::max(deepest, need[n.child[c]]);
    }
    need[i] = (children > 0 ? children - 1 : 0) + deepest;
  }
  return nodes.empty() ? 0 : need[0];
}

}  // namespace tracer
