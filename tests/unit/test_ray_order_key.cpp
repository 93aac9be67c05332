// The rays' sort key (kernel/geom/ray_order_key.h) against a Morton code written another way:
// the key's 30 bits read from the most significant as a string, position p holding bit
// 4 - p / 6 of cell coordinate p % 6 (origin x, y, z, direction x, y, z); the cells at their
// edges, for NaN and outside the box; and the CPU's radix sort by the key
// (render/ray_order_sort.h) against std::stable_sort.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "render/ray_order_sort.h"

#include "kernel/base/philox.h"
#include "kernel/geom/ray_order_key.h"

using namespace tracer;

namespace {

// The key spelled as the bit string the interleave should give, from six cell coordinates.
std::string expected_bits(const uint32_t cells[6]) {
  std::string bits;
  for (int p = 0; p < 30; ++p) bits += ((cells[p % 6] >> (4 - p / 6)) & 1u) ? '1' : '0';
  return bits;
}

std::string bits_of_key(uint32_t key) {
  std::string bits;
  for (int b = 29; b >= 0; --b) bits += ((key >> b) & 1u) ? '1' : '0';
  return bits;
}

// The box [-16, 16]^3: 32 cells of width 1 on each axis, whose edges are exact in float.
const RayOrderFrame kFrame = ray_order_frame({-16.0f, -16.0f, -16.0f}, {16.0f, 16.0f, 16.0f});

}  // namespace

TEST(RayOrderKey, InterleavesTheSixCellsBitsFromTheMostSignificant) {
  for (uint32_t i = 0; i < 2000; ++i) {
    const Philox4 r = philox4x32_10({{i, 0u, 0u, 0u}}, 0x0DDBA11u, 0x5EEDu);
    uint32_t cells[6];
    for (uint32_t a = 0; a < 6; ++a) cells[a] = (r.v[a % 4] >> (a < 4 ? 0 : 16)) & 31u;
    // each coordinate at the middle of its cell: origin cells of width 1 from -16, direction
    // cells of width 1/16 from -1
    const Vec3 origin = {cells[0] - 15.5f, cells[1] - 15.5f, cells[2] - 15.5f};
    const Vec3 dir = {(cells[3] + 0.5f) / 16.0f - 1.0f, (cells[4] + 0.5f) / 16.0f - 1.0f,
                      (cells[5] + 0.5f) / 16.0f - 1.0f};
    ASSERT_EQ(bits_of_key(ray_order_key(kFrame, origin, dir)), expected_bits(cells)) << i;
  }
}

TEST(RayOrderKey, CellsStartAtTheirLowerEdgeAndClampOutsideTheBox) {
  EXPECT_EQ(ray_order_cell(-16.0f, -16.0f, 1.0f), 0u);
  EXPECT_EQ(ray_order_cell(std::nextafter(-15.0f, -16.0f), -16.0f, 1.0f), 0u);
  EXPECT_EQ(ray_order_cell(-15.0f, -16.0f, 1.0f), 1u);
  EXPECT_EQ(ray_order_cell(15.0f, -16.0f, 1.0f), 31u);
  EXPECT_EQ(ray_order_cell(16.0f, -16.0f, 1.0f), 31u);  // the box's far face: the last cell
  EXPECT_EQ(ray_order_cell(1e30f, -16.0f, 1.0f), 31u);
  EXPECT_EQ(ray_order_cell(std::numeric_limits<float>::infinity(), -16.0f, 1.0f), 31u);
  EXPECT_EQ(ray_order_cell(-17.0f, -16.0f, 1.0f), 0u);
  EXPECT_EQ(ray_order_cell(-std::numeric_limits<float>::infinity(), -16.0f, 1.0f), 0u);
  EXPECT_EQ(ray_order_cell(std::numeric_limits<float>::quiet_NaN(), -16.0f, 1.0f), 0u);
  // directions: -1 the first cell, +1 the last, 0 the first of the upper half
  const Vec3 o = {-16.0f, -16.0f, -16.0f};
  EXPECT_EQ(ray_order_key(kFrame, o, {-1.0f, -1.0f, -1.0f}), 0u);
  EXPECT_EQ(ray_order_key(kFrame, {16.0f, 16.0f, 16.0f}, {1.0f, 1.0f, 1.0f}), (1u << kRayOrderKeyBits) - 1u);
  EXPECT_EQ(ray_order_key(kFrame, o, {0.0f, -1.0f, -1.0f}), 1u << 26);                        // direction x's top bit
  EXPECT_EQ(ray_order_key(kFrame, {0.0f, -16.0f, -16.0f}, {-1.0f, -1.0f, -1.0f}), 1u << 29);  // origin x's
}

TEST(RayOrderKey, AFlatBoxPutsEveryOriginInTheFirstCellOfItsFlatAxis) {
  const RayOrderFrame flat = ray_order_frame({0.0f, 2.0f, 0.0f}, {32.0f, 2.0f, 32.0f});
  EXPECT_EQ(flat.scale.y, 0.0f);
  for (const float y : {2.0f, -5.0f, 7.0f})
    EXPECT_EQ(ray_order_key(flat, {31.5f, y, 0.5f}, {-1.0f, -1.0f, -1.0f}),
              1u << 29 | 1u << 23 | 1u << 17 | 1u << 11 | 1u << 5)
        << y;
}

TEST(CpuRaySorter, GivesTheStableSortByKeyForAnyThreadCountOfASetOrAQueue) {
  const Vec3 lo = {-2.0f, 0.0f, 1.0f}, hi = {3.0f, 0.5f, 9.0f};
  const RayOrderFrame frame = ray_order_frame(lo, hi);
  std::vector<Ray> rays;
  for (uint32_t i = 0; i < 20000; ++i) {
    const Philox4 r = philox4x32_10({{i, 1u, 0u, 0u}}, 0x0DDBA11u, 0x5EEDu);
    const float u[4] = {uniform_from_bits(r.v[0]), uniform_from_bits(r.v[1]), uniform_from_bits(r.v[2]),
                        uniform_from_bits(r.v[3])};
    // few distinct origins, so that many keys are equal and the order among them is tested
    const Vec3 origin = {lo.x + std::floor(u[0] * 4.0f) * (hi.x - lo.x) / 4.0f, lo.y + u[1] * 0.1f, hi.z};
    rays.push_back({origin, normalize(Vec3{u[2] - 0.5f, u[3] - 0.5f, 0.25f})});
  }
  std::vector<uint32_t> expected(rays.size());
  std::iota(expected.begin(), expected.end(), 0u);
  std::stable_sort(expected.begin(), expected.end(), [&](uint32_t a, uint32_t b) {
    return ray_order_key(frame, rays[a].origin, rays[a].dir) < ray_order_key(frame, rays[b].origin, rays[b].dir);
  });
  CpuRaySorter sorter(rays.size());
  for (const int threads : {1, 2, 3}) EXPECT_EQ(sorter.sort(rays, frame, threads), expected) << threads;
  const std::vector<Ray> none, one = {rays[7]};
  EXPECT_TRUE(sorter.sort(none, frame, 2).empty());
  EXPECT_EQ(sorter.sort(one, frame, 2), std::vector<uint32_t>{0u});
  EXPECT_THROW(CpuRaySorter(3).sort(rays, frame, 1), std::length_error);

  // A stream queue: state indices, some states absent, in no order. Sorting it gives the
  // queue's entries stably sorted by their states' keys.
  std::vector<Vec3> origin, dir;
  for (const Ray& ray : rays) origin.push_back(ray.origin), dir.push_back(ray.dir);
  std::vector<uint32_t> queue;
  for (uint32_t k = 0; k < rays.size(); k += 3) queue.push_back((k * 7919u) % static_cast<uint32_t>(rays.size()));
  std::vector<uint32_t> sorted_queue = queue;
  std::stable_sort(sorted_queue.begin(), sorted_queue.end(), [&](uint32_t a, uint32_t b) {
    return ray_order_key(frame, origin[a], dir[a]) < ray_order_key(frame, origin[b], dir[b]);
  });
  for (const int threads : {1, 2, 3}) {
    std::vector<uint32_t> q = queue;
    sorter.sort_queue(q.data(), q.size(), origin.data(), dir.data(), frame, threads);
    EXPECT_EQ(q, sorted_queue) << threads;
  }
}
