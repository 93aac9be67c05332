// The linear BVH's build steps (Karras, "Maximizing Parallelism in the Construction of
// BVHs, Octrees, and k-d Trees", HPG 2012) as kernel functions, one item or node per call,
// so that an OpenMP loop (tracer/accel/lbvh_builder.cpp), std::threads (the GPU runner's CPU side)
// and a CUDA grid (cuda/lbvh_gpu.cu) run the same code and give the same nodes bit for bit:
// Morton keys, the binary radix tree (each internal node independently), the bottom-up
// boxes (the second child to arrive at a node merges them) and the layout into BvhNodes.
#pragma once
#include "kernel/accel/bvh_node.h"
#include "kernel/base/float_to_int.h"

namespace tracer {

constexpr uint32_t kLbvhNoParent = 0xffffffffu;

struct LbvhBox {
  Vec3 lo, hi;
};

// Internal node i of n - 1; child ids below n - 1 are internal nodes, id n - 1 + k is leaf k.
struct LbvhInner {
  uint32_t left, right;
};

TRACER_HD uint32_t spread_bits(uint32_t v) {  // 10 bits to every third bit
  v = (v * 0x00010001u) & 0xFF0000FFu;
  v = (v * 0x00000101u) & 0x0F00F00Fu;
  v = (v * 0x00000011u) & 0xC30C30C3u;
  v = (v * 0x00000005u) & 0x49249249u;
  return v;
}

// 10 bits per axis interleaved, x highest, from coordinates in [0, 1].
TRACER_HD uint32_t morton_code(Vec3 unit) {
  const uint32_t x = trunc_to_uint32(clamp_of(unit.x * 1024.0f, 0.0f, 1023.0f));
  const uint32_t y = trunc_to_uint32(clamp_of(unit.y * 1024.0f, 0.0f, 1023.0f));
  const uint32_t z = trunc_to_uint32(clamp_of(unit.z * 1024.0f, 0.0f, 1023.0f));
  return spread_bits(x) << 2 | spread_bits(y) << 1 | spread_bits(z);
}

// The sort key: the centroid's Morton code in the centroids' box (lo, 1 / extent), then the
// primitive id, so every key is distinct and any correct sort gives the same order.
TRACER_HD uint64_t lbvh_key(Vec3 centroid, Vec3 lo, Vec3 scale, uint32_t id) {
  return uint64_t(morton_code((centroid - lo) * scale)) << 32 | id;
}

// Karras's delta: the common prefix of keys i and j, -1 outside [0, n).
TRACER_HD int lbvh_delta(const uint64_t* keys, int n, int i, int j) {
  return j < 0 || j >= n ? -1 : count_leading_zeros(keys[i] ^ keys[j]);
}

// Internal node i (Karras, Figure 4): its key range by exponential then binary search,
// its split by binary search; writes inner[i] and its children's parent entries.
TRACER_HD void lbvh_radix_node(const uint64_t* keys, int n, int i, LbvhInner* inner, uint32_t* parent) {
  const int d = lbvh_delta(keys, n, i, i + 1) > lbvh_delta(keys, n, i, i - 1) ? 1 : -1;
  const int delta_min = lbvh_delta(keys, n, i, i - d);
  int l_max = 2;
  while (lbvh_delta(keys, n, i, i + l_max * d) > delta_min) l_max *= 2;
  int l = 0;
  for (int t = l_max / 2; t >= 1; t /= 2)
    if (lbvh_delta(keys, n, i, i + (l + t) * d) > delta_min) l += t;
  const int j = i + l * d;
  const int delta_node = lbvh_delta(keys, n, i, j);
  int s = 0;
  for (int t = (l + 1) / 2;; t = (t + 1) / 2) {
    if (lbvh_delta(keys, n, i, i + (s + t) * d) > delta_node) s += t;
    if (t == 1) break;
  }
  const int gamma = i + s * d + min_of(d, 0);
  const uint32_t leaves = static_cast<uint32_t>(n - 1);
  const uint32_t left = min_of(i, j) == gamma ? leaves + gamma : gamma;
  const uint32_t right = max_of(i, j) == gamma + 1 ? leaves + gamma + 1 : gamma + 1;
  inner[i] = {left, right};
  parent[left] = static_cast<uint32_t>(i);
  parent[right] = static_cast<uint32_t>(i);
  if (i == 0) parent[0] = kLbvhNoParent;
}

TRACER_HD LbvhBox lbvh_load_box(const LbvhBox& b) {
  const float* f = &b.lo.x;  // lo.x, lo.y, lo.z, hi.x, hi.y, hi.z
  return {{load_shared_float(f), load_shared_float(f + 1), load_shared_float(f + 2)},
          {load_shared_float(f + 3), load_shared_float(f + 4), load_shared_float(f + 5)}};
}

// From leaf `leaf` up: the first child to arrive at a node stops, the second merges both
// boxes (min/max: the same whichever arrives first) and climbs on. `visits` starts at 0.
TRACER_HD void lbvh_climb(int leaf, int n, const LbvhInner* inner, const uint32_t* parent, const LbvhBox* leaf_boxes,
                          LbvhBox* boxes, uint32_t* visits) {
  const uint32_t leaves = static_cast<uint32_t>(n - 1);
  uint32_t node = parent[leaves + leaf];
  while (node != kLbvhNoParent) {
    if (atomic_increment(&visits[node]) == 0) return;  // the sibling's climb will finish this node
    const uint32_t l = inner[node].left, r = inner[node].right;
    const LbvhBox a = l >= leaves ? leaf_boxes[l - leaves] : lbvh_load_box(boxes[l]);
    const LbvhBox b = r >= leaves ? leaf_boxes[r - leaves] : lbvh_load_box(boxes[r]);
    boxes[node] = {min_of(a.lo, b.lo), max_of(a.hi, b.hi)};
    node = parent[node];
  }
}

// The tree in BvhNode order, breadth-first, each node's two children adjacent; leaf k
// indexes position k of the Morton-sorted items. `queue` holds n - 1 (radix node,
// position) pairs, 2n - 2 words; `nodes` gets 2n - 1 entries. Sequential: one thread lays out the tree.
TRACER_HD void lbvh_lay_out(int n, const LbvhInner* inner, const LbvhBox* boxes, const LbvhBox* leaf_boxes,
                            uint32_t* queue, BvhNode* nodes) {
  const uint32_t leaves = static_cast<uint32_t>(n - 1);
  uint32_t queued = 1, next = 1;
  queue[0] = 0, queue[1] = 0;
  for (uint32_t q = 0; q < queued; ++q) {
    const uint32_t radix = queue[2 * q], position = queue[2 * q + 1];
    nodes[position] = {boxes[radix].lo, next, boxes[radix].hi, 0u};
    const uint32_t children[2] = {inner[radix].left, inner[radix].right};
    for (uint32_t k = 0; k < 2; ++k) {
      const uint32_t c = children[k];
      if (c >= leaves) {
        nodes[next + k] = {leaf_boxes[c - leaves].lo, c - leaves, leaf_boxes[c - leaves].hi, 1u};
      } else {
        queue[2 * queued] = c, queue[2 * queued + 1] = next + k;
        ++queued;
      }
    }
    next += 2;
  }
}

}  // namespace tracer
