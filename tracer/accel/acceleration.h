// Builds the scene's acceleration structure (render.accel): fills scene.bounded (the
// primitive ids a BVH's leaves index, in leaf order) and scene.unbounded (planes, tested
// for every ray), then the arrays of the chosen structure.
#pragma once
#include "scene/scene.h"

namespace tracer {

void build_acceleration(Scene& scene);

// World-space padding of primitive bounds for the kd-tree and the grid: 2^-18 of the
// largest coordinate magnitude or extent, many ulps beyond any rounding of cell boundaries.
float structure_pad(Vec3 lo, Vec3 hi);

// What `tracer info` and `--stats` report of the built structure: its name as --accel
// spells it, its nodes (bvh, lbvh, kd-trees) and its cells (grid).
struct AccelSummary {
  std::string name;
  size_t nodes = 0, cells = 0;
};
AccelSummary acceleration_summary(const Scene& scene);

// Bytes the built structure occupies (nodes, cells and index arrays), for `bench rays`.
size_t acceleration_bytes(const Scene& scene);

}  // namespace tracer
