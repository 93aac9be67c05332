// The SAH build (accel/bvh_builder.h) makes the same tree whichever thread built what: the
// nodes, the leaf order and the 8-wide collapse are the same bytes for 1, 2, 3 and 8 threads,
// on a mesh large enough that its halves are tasks and its top ranges are binned in chunks
// and on one small enough for the smallest tasks. Planes anywhere among the primitives, chunk
// boundaries included, leave the tree of the other primitives as it was. A chain of far
// clusters, each split off the rest on its own, stays inside the slots the build reserves.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>

#include "accel/acceleration.h"
#include "bench/mesh_generators.h"

namespace tracer {
namespace {

std::vector<Primitive> triangles_of(const std::string& kind, uint32_t count) {
  std::vector<Primitive> primitives;
  for (const MeshTriangle& t : generate_mesh(kind, count))
    primitives.push_back({ShapeKind::Triangle, 0, -1, 0.0f, t.p[0], t.p[1], t.p[2]});
  return primitives;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

Acceleration build_with_threads(std::span<const Primitive> primitives, int threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Acceleration a = build_acceleration(AccelKind::Bvh, primitives, 0);
  omp_set_num_threads(before);
  return a;
}

TEST(BvhBuild, TheTreeIsTheSameForAnyThreadCount) {
  // 300,000 triangles: ranges past 2^18 items are binned in chunks, halves past 2^13 are tasks;
  // 20,000: just past the smallest build made by more than one thread, halves of 2^10 items.
  for (const auto& [kind, count] : {std::pair<const char*, uint32_t>{"terrain", 300000}, {"sphere", 20000}}) {
    const std::vector<Primitive> primitives = triangles_of(kind, count);
    const Acceleration one = build_with_threads(primitives, 1);
    ASSERT_GT(one.bvh_nodes.size(), 1u) << kind;
    ASSERT_EQ(one.bounded.size(), primitives.size()) << kind;
    for (const int threads : {2, 3, 8}) {
      const Acceleration many = build_with_threads(primitives, threads);
      EXPECT_TRUE(same_bytes(many.bvh_nodes, one.bvh_nodes)) << kind << ", " << threads << " threads: nodes";
      EXPECT_EQ(many.bounded, one.bounded) << kind << ", " << threads << " threads: leaf order";
      EXPECT_TRUE(same_bytes(many.wide.nodes, one.wide.nodes)) << kind << ", " << threads << " threads: wide nodes";
      EXPECT_TRUE(same_bytes(many.wide.blocks, one.wide.blocks)) << kind << ", " << threads << " threads: blocks";
    }
  }
}

TEST(BvhBuild, PlanesAmongThePrimitivesLeaveTheTreeOfTheOthers) {
  const std::vector<Primitive> triangles = triangles_of("sphere", 70000);  // more than one chunk of 2^16
  const Primitive plane = {ShapeKind::Plane, 0, -1, 0.0f, {0, -2, 0}, {0, 1, 0}, {}};
  // Planes first, on the chunk boundary, and last.
  const std::vector<size_t> plane_at = {0, 65536, triangles.size() + 2};
  std::vector<Primitive> mixed;
  std::vector<uint32_t> id_in_mixed;  // a triangle's id among `mixed`
  for (size_t i = 0; i < triangles.size(); ++i) {
    while (std::find(plane_at.begin(), plane_at.end(), mixed.size()) != plane_at.end()) mixed.push_back(plane);
    id_in_mixed.push_back(static_cast<uint32_t>(mixed.size()));
    mixed.push_back(triangles[i]);
  }
  mixed.push_back(plane);
  ASSERT_EQ(mixed.size(), triangles.size() + 3);
  const Acceleration alone = build_acceleration(AccelKind::Bvh, triangles, 0);
  const Acceleration with_planes = build_acceleration(AccelKind::Bvh, mixed, 0);
  EXPECT_TRUE(same_bytes(with_planes.bvh_nodes, alone.bvh_nodes));
  ASSERT_EQ(with_planes.bounded.size(), alone.bounded.size());
  for (size_t i = 0; i < alone.bounded.size(); ++i)
    ASSERT_EQ(with_planes.bounded[i], id_in_mixed[alone.bounded[i]]) << "leaf position " << i;
  EXPECT_EQ(with_planes.unbounded, (std::vector<uint32_t>{0, 65536, static_cast<uint32_t>(mixed.size() - 1)}));
}

// A lump of 1,100 triangles at the origin and 60 clusters of 9 along x at 1.5^k: the SAH splits
// the farthest cluster or two off at each level, so the nodes over 2^10 items or more (the task
// size here) form a chain and each cluster's subtree, built by one thread, takes its own slots.
TEST(BvhBuild, AChainOfFarClustersStaysInTheReservedSlots) {
  std::vector<Primitive> primitives;
  const auto triangle_at = [&](float x, float y, float z) {
    primitives.push_back({ShapeKind::Triangle, 0, -1, 0.0f, {x, y, z}, {x + 0.5f, y, z}, {x, y + 0.5f, z + 0.25f}});
  };
  for (int i = 0; i < 1100; ++i)
    triangle_at(0.01f * static_cast<float>(i % 33), 0.01f * static_cast<float>(i / 33), 0.0f);
  float x = 1.0f;
  for (int k = 0; k < 60; ++k) {
    x *= 1.5f;
    for (int i = 0; i < 9; ++i) triangle_at(x + 0.01f * static_cast<float>(i), 0.01f * static_cast<float>(i), 0.0f);
  }
  const Acceleration a = build_with_threads(primitives, 2);
  // The chain: interior nodes over 2^10 items or more with a child under 2^10 that is split again.
  std::vector<uint32_t> items(a.bvh_nodes.size(), 0);
  for (size_t i = a.bvh_nodes.size(); i-- > 0;) {
    const BvhNode& n = a.bvh_nodes[i];
    items[i] = n.count != 0 ? n.count : items[n.first] + items[n.first + 1];
  }
  uint32_t split_off = 0;
  for (size_t i = 0; i < a.bvh_nodes.size(); ++i) {
    const BvhNode& n = a.bvh_nodes[i];
    if (n.count != 0 || items[i] < 1024) continue;
    for (const uint32_t child : {n.first, n.first + 1})
      split_off += items[child] < 1024 && a.bvh_nodes[child].count == 0;
  }
  EXPECT_GE(split_off, 10u) << "the scene no longer makes the chain this test is about";
  std::vector<uint32_t> ids = a.bounded;
  std::sort(ids.begin(), ids.end());
  for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i) << "every primitive in one leaf";
  EXPECT_EQ(build_with_threads(primitives, 1).bvh_nodes.size(), a.bvh_nodes.size());
}

}  // namespace
}  // namespace tracer
