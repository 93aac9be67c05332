// Builds the acceleration structure render.accel names over a scene's primitives: the
// bounded primitives' ids (in BVH leaf order), the unbounded ones (planes, tested for every
// ray), and the arrays of the chosen structure. The builders take the primitives and return
// arrays; the scene loader moves them into the Scene.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "accel/accel_summary.h"
#include "accel/grid_builder.h"
#include "accel/kdtree_builder.h"
#include "accel/wide_bvh_builder.h"
#include "kernel/accel/bvh_node.h"
#include "kernel/scene/render_settings.h"

namespace tracer {

struct Acceleration {
  std::vector<uint32_t> bounded, unbounded;
  std::vector<BvhNode> bvh_nodes;  // bvh and lbvh
  WideBvh wide;                    // bvh: the CPU's 8-wide collapse of bvh_nodes
  KdTree kd;                       // kdtree and kdtree-median
  UniformGrid grid;                // grid
};

Acceleration build_acceleration(AccelKind kind, std::span<const Primitive> primitives, uint32_t grid_resolution);

// World-space padding of primitive bounds for the kd-tree and the grid: 2^-18 of the
// largest coordinate magnitude or extent, many ulps beyond any rounding of cell boundaries.
float structure_pad(Vec3 lo, Vec3 hi);

AccelSummary acceleration_summary(AccelKind kind, const Acceleration& a);

// Bytes the built structure occupies (nodes, cells and index arrays), for `bench rays`.
size_t acceleration_bytes(const Acceleration& a);

}  // namespace tracer
