// A 30-bit sort key that brings rays starting near each other and pointing the same way
// together (after Garanzha and Loop, "Fast Ray Sorting and Breadth-First Packet Traversal for
// GPU Ray Tracing", Eurographics 2010, who sort rays by their quantized origin and direction):
// the origin's cell on a 32^3 grid over a box [lo, hi] and the direction's on a 32^3 grid over
// [-1, 1]^3, the six 5-bit cell coordinates' bits interleaved from the most significant (a
// Morton code of the 6-D point: origin x, y, z, then direction x, y, z, at each bit). Tracing
// rays in this order changes no hit; it only changes which rays run side by side.
#pragma once
#include <cstdint>

#include "kernel/base/float_to_int.h"
#include "kernel/base/vec3.h"

namespace tracer {

constexpr uint32_t kRayOrderCellBits = 5;
constexpr uint32_t kRayOrderKeyBits = 6 * kRayOrderCellBits;

// The cell of x on kRayOrderCells cells of width 1 / scale from lo: NaN and below lo give the
// first, beyond the last cell the last.
TRACER_HD uint32_t ray_order_cell(float x, float lo, float scale) {
  constexpr uint32_t kLast = (1u << kRayOrderCellBits) - 1u;
  const uint32_t c = trunc_to_uint32((x - lo) * scale);
  return c < kLast ? c : kLast;
}

// What ray_order_key needs of the box, computed once: its corner and cells per unit on each
// axis (0 along an axis where the box is flat, so every origin takes that axis' first cell).
struct RayOrderFrame {
  Vec3 lo, scale;
};

inline RayOrderFrame ray_order_frame(Vec3 lo, Vec3 hi) {
  constexpr float kCells = static_cast<float>(1u << kRayOrderCellBits);
  const auto per_unit = [](float extent) { return extent > 0.0f ? kCells / extent : 0.0f; };
  return {lo, {per_unit(hi.x - lo.x), per_unit(hi.y - lo.y), per_unit(hi.z - lo.z)}};
}

TRACER_HD uint32_t ray_order_key(const RayOrderFrame& frame, Vec3 origin, Vec3 dir) {
  constexpr float kDirScale = static_cast<float>(1u << kRayOrderCellBits) * 0.5f;  // [-1, 1] over the cells
  const uint32_t cells[6] = {ray_order_cell(origin.x, frame.lo.x, frame.scale.x),
                             ray_order_cell(origin.y, frame.lo.y, frame.scale.y),
                             ray_order_cell(origin.z, frame.lo.z, frame.scale.z),
                             ray_order_cell(dir.x, -1.0f, kDirScale),
                             ray_order_cell(dir.y, -1.0f, kDirScale),
                             ray_order_cell(dir.z, -1.0f, kDirScale)};
  uint32_t key = 0;
  for (uint32_t bit = kRayOrderCellBits; bit-- > 0;)
    for (uint32_t axis = 0; axis < 6; ++axis) key = (key << 1) | ((cells[axis] >> bit) & 1u);
  return key;
}

}  // namespace tracer
