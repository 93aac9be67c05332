#include "lbvh_builder.h"

#include <omp.h>

#include <algorithm>
#include <atomic>

namespace tracer {
namespace {

uint32_t spread_bits(uint32_t v) {  // 10 bits to every third bit
  v = (v * 0x00010001u) & 0xFF0000FFu;
  v = (v * 0x00000101u) & 0x0F00F00Fu;
  v = (v * 0x00000011u) & 0xC30C30C3u;
  v = (v * 0x00000005u) & 0x49249249u;
  return v;
}

struct RadixNode {
  uint32_t left, right;  // child ids: < n - 1 internal, else leaf (id - (n - 1))
  uint32_t parent;
};

}  // namespace

uint32_t morton_code(Vec3 unit) {
  const auto q = [](float v) { return static_cast<uint32_t>(std::clamp(v * 1024.0f, 0.0f, 1023.0f)); };
  return spread_bits(q(unit.x)) << 2 | spread_bits(q(unit.y)) << 1 | spread_bits(q(unit.z));
}

std::vector<BvhNode> build_lbvh(std::vector<BuildItem>& items) {
  const int n = static_cast<int>(items.size());
  if (n == 0) return {};
  if (n == 1) return {{items[0].bounds.lo, 0u, items[0].bounds.hi, 1u}};
  Bounds centroids;
  for (const BuildItem& it : items) centroids.grow(it.centroid);
  const Vec3 extent = centroids.hi - centroids.lo;
  const Vec3 scale = {extent.x > 0 ? 1 / extent.x : 0, extent.y > 0 ? 1 / extent.y : 0, extent.z > 0 ? 1 / extent.z : 0};
  std::vector<uint64_t> key(n);
#pragma omp parallel for
  for (int i = 0; i < n; ++i)
    key[i] = uint64_t(morton_code((items[i].centroid - centroids.lo) * scale)) << 32 | items[i].id;
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  std::vector<BuildItem> sorted(n);
  std::vector<uint64_t> sorted_key(n);
  for (int i = 0; i < n; ++i) sorted[i] = items[order[i]], sorted_key[i] = key[order[i]];
  items.swap(sorted);

  // Radix tree (Karras, Figure 4): every internal node i finds its range and split.
  const auto delta = [&](int i, int j) { return j < 0 || j >= n ? -1 : __builtin_clzll(sorted_key[i] ^ sorted_key[j]); };
  std::vector<RadixNode> inner(n - 1);
  std::vector<uint32_t> leaf_parent(n);
#pragma omp parallel for
  for (int i = 0; i < n - 1; ++i) {
    const int d = delta(i, i + 1) > delta(i, i - 1) ? 1 : -1;
    const int delta_min = delta(i, i - d);
    int l_max = 2;
    while (delta(i, i + l_max * d) > delta_min) l_max *= 2;
    int l = 0;
    for (int t = l_max / 2; t >= 1; t /= 2)
      if (delta(i, i + (l + t) * d) > delta_min) l += t;
    const int j = i + l * d;
    const int delta_node = delta(i, j);
    int s = 0;
    for (int t = (l + 1) / 2;; t = (t + 1) / 2) {
      if (delta(i, i + (s + t) * d) > delta_node) s += t;
      if (t == 1) break;
    }
    const int gamma = i + s * d + std::min(d, 0);
    const uint32_t leaves = static_cast<uint32_t>(n - 1);
    inner[i].left = std::min(i, j) == gamma ? leaves + gamma : gamma;
    inner[i].right = std::max(i, j) == gamma + 1 ? leaves + gamma + 1 : gamma + 1;
  }
  for (int i = 0; i < n - 1; ++i)
    for (uint32_t c : {inner[i].left, inner[i].right}) {
      if (c >= uint32_t(n - 1)) leaf_parent[c - (n - 1)] = i;
      else inner[c].parent = i;
    }

  // Bottom-up boxes: from every leaf, climb; the second visitor of a node computes its box.
  std::vector<Bounds> box(n - 1);
  std::vector<std::atomic<int>> visits(n - 1);
  for (auto& v : visits) v.store(0);
  const auto child_box = [&](uint32_t c) { return c >= uint32_t(n - 1) ? items[c - (n - 1)].bounds : box[c]; };
#pragma omp parallel for
  for (int leaf = 0; leaf < n; ++leaf) {
    uint32_t node = leaf_parent[leaf];
    for (;;) {
      if (visits[node].fetch_add(1) == 0) break;  // the sibling's climb will finish this node
      Bounds b = child_box(inner[node].left);
      b.grow(child_box(inner[node].right));
      box[node] = b;
      if (node == 0) break;
      node = inner[node].parent;
    }
  }

  // Lay out in BvhNode order, breadth-first, each node's two children adjacent; leaf k
  // indexes position k of the sorted items (scene.bounded).
  std::vector<BvhNode> nodes(2 * size_t(n) - 1);
  std::vector<std::pair<uint32_t, uint32_t>> queue = {{0u, 0u}};  // (radix node, position)
  uint32_t next = 1;
  for (size_t q = 0; q < queue.size(); ++q) {
    const auto [radix, position] = queue[q];
    nodes[position] = {box[radix].lo, next, box[radix].hi, 0u};
    const uint32_t children[2] = {inner[radix].left, inner[radix].right};
    for (uint32_t k = 0; k < 2; ++k) {
      const uint32_t c = children[k];
      if (c >= uint32_t(n - 1)) {
        const uint32_t leaf = c - uint32_t(n - 1);
        nodes[next + k] = {items[leaf].bounds.lo, leaf, items[leaf].bounds.hi, 1u};
      } else {
        queue.push_back({c, next + k});
      }
    }
    next += 2;
  }
  return nodes;
}

}  // namespace tracer
