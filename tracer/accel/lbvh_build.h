// The LBVH build as a sequence of kernel/accel/lbvh.h steps, with the parallel loop as a
// parameter: the tracer passes an OpenMP loop (lbvh_builder.cpp), the GPU runner's CPU side
// std::threads; cuda/lbvh_gpu.cu runs the same steps as CUDA grids. The steps' results do
// not depend on the schedule, so every scheduler gives the same nodes bit for bit.
#pragma once
#include <algorithm>
#include <vector>

#include "kernel/accel/lbvh.h"

namespace tracer {

struct LbvhInput {
  std::vector<LbvhBox> boxes;
  std::vector<Vec3> centroids;
  std::vector<uint32_t> ids;  // primitive ids: the keys' tie-break
};

struct LbvhTree {
  std::vector<BvhNode> nodes;   // 2n - 1; leaf k refers to position k of `order`
  std::vector<uint32_t> order;  // input indices in Morton order
};

// The centroids' box as its low corner and 1 / extent per axis (0 for a flat axis).
inline void lbvh_frame(const std::vector<Vec3>& centroids, Vec3& lo, Vec3& scale) {
  lo = {kInfinity, kInfinity, kInfinity};
  Vec3 hi = {-kInfinity, -kInfinity, -kInfinity};
  for (const Vec3& c : centroids) lo = min_of(lo, c), hi = max_of(hi, c);
  const Vec3 extent = hi - lo;
  scale = {extent.x > 0 ? 1 / extent.x : 0, extent.y > 0 ? 1 / extent.y : 0, extent.z > 0 ? 1 / extent.z : 0};
}

// parallel_for(count, fn) calls fn(i) for every i in [0, count), in any order and on any thread.
template <class ParallelFor>
LbvhTree build_lbvh_tree(const LbvhInput& in, ParallelFor parallel_for) {
  const int n = static_cast<int>(in.boxes.size());
  LbvhTree tree;
  if (n == 0) return tree;
  if (n == 1) return {{{in.boxes[0].lo, 0u, in.boxes[0].hi, 1u}}, {0u}};
  Vec3 lo, scale;
  lbvh_frame(in.centroids, lo, scale);
  std::vector<uint64_t> key(n), sorted_key(n);
  parallel_for(n, [&](size_t i) { key[i] = lbvh_key(in.centroids[i], lo, scale, in.ids[i]); });
  tree.order.resize(n);
  for (int i = 0; i < n; ++i) tree.order[i] = static_cast<uint32_t>(i);
  std::sort(tree.order.begin(), tree.order.end(), [&](uint32_t a, uint32_t b) { return key[a] < key[b]; });
  std::vector<LbvhBox> leaf_boxes(n);
  for (int i = 0; i < n; ++i) sorted_key[i] = key[tree.order[i]], leaf_boxes[i] = in.boxes[tree.order[i]];

  std::vector<LbvhInner> inner(n - 1);
  std::vector<uint32_t> parent(2 * size_t(n) - 1), visits(n - 1, 0u);
  std::vector<LbvhBox> boxes(n - 1);
  parallel_for(n - 1, [&](size_t i) {
    lbvh_radix_node(sorted_key.data(), n, static_cast<int>(i), inner.data(), parent.data());
  });
  parallel_for(n, [&](size_t leaf) {
    lbvh_climb(static_cast<int>(leaf), n, inner.data(), parent.data(), leaf_boxes.data(), boxes.data(), visits.data());
  });
  tree.nodes.resize(2 * size_t(n) - 1);
  std::vector<uint32_t> queue(2 * size_t(n - 1));
  lbvh_lay_out(n, inner.data(), boxes.data(), leaf_boxes.data(), queue.data(), tree.nodes.data());
  return tree;
}

}  // namespace tracer
