#include "bundle/bundle_references.h"

#include <cmath>
#include <vector>

#include "kernel/accel/traverse_bvh_pairs.h"
#include "kernel/accel/traverse_wide_bvh.h"
#include "kernel/light/environment_light.h"

namespace tracer {
namespace {

constexpr uint32_t kMaterialKindCount = 0
#define TRACER_COUNT_MATERIAL(Kind, ...) +1
    TRACER_MATERIAL_KINDS(TRACER_COUNT_MATERIAL)
#undef TRACER_COUNT_MATERIAL
    ;

// How many interior nodes may lie above an interior node: the binary walks (traverse_bvh.h,
// the pair records' walk) push at most one entry per interior node above, the 8-wide walk
// seven, and their stacks hold kBvhPairStackSize and kWideStackSize entries.
constexpr uint32_t kBinaryInteriorAbove = kBvhPairStackSize - 1;
constexpr uint32_t kWideInteriorAbove = kWideStackSize / (kWideBvhWidth - 1) - 1;

std::string at(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]: "; }

std::string of(uint64_t index, size_t size, const char* what) {
  return std::to_string(index) + " of " + std::to_string(size) + " " + what;
}

std::string primitive_ids(const char* array, const std::vector<uint32_t>& ids, size_t primitives) {
  for (size_t i = 0; i < ids.size(); ++i)
    if (ids[i] >= primitives) return at(array, i) + "primitive " + of(ids[i], primitives, "primitives");
  return "";
}

// A structure's primitives: in range, and no plane (planes are unbounded, tested before any
// walk; a structure's leaves test without them, kernel/accel/primitive_hit.h).
std::string bounded_ids(const char* array, const std::vector<uint32_t>& ids, const std::vector<Primitive>& primitives) {
  const std::string range = primitive_ids(array, ids, primitives.size());
  if (!range.empty()) return range;
  for (size_t i = 0; i < ids.size(); ++i)
    if (primitives[ids[i]].kind == ShapeKind::Plane)
      return at(array, i) + "primitive " + std::to_string(ids[i]) + " is a plane, which no structure holds";
  return "";
}

bool texture_or_none(uint32_t t, size_t textures) { return t == kNoTexture || t < textures; }

std::string materials_violation(const SceneArrays& a) {
  for (size_t i = 0; i < a.materials.size(); ++i) {
    const Material& m = a.materials[i];
    if (static_cast<uint32_t>(m.kind) >= kMaterialKindCount)
      return at("materials", i) + "kind " + std::to_string(static_cast<uint32_t>(m.kind));
    if (static_cast<uint32_t>(m.fresnel) > static_cast<uint32_t>(FresnelKind::Exact))
      return at("materials", i) + "Fresnel model " + std::to_string(static_cast<uint32_t>(m.fresnel));
    if (static_cast<uint32_t>(m.alpha_mode) > static_cast<uint32_t>(AlphaMode::Blend))
      return at("materials", i) + "alpha mode " + std::to_string(static_cast<uint32_t>(m.alpha_mode));
    for (const uint32_t t : m.texture)
      if (!texture_or_none(t, a.textures.size()))
        return at("materials", i) + "texture " + of(t, a.textures.size(), "textures");
    for (const uint32_t t : {m.factor_map, m.normal_map, m.bump_map, m.alpha_map})
      if (!texture_or_none(t, a.textures.size()))
        return at("materials", i) + "map " + of(t, a.textures.size(), "textures");
    if (m.alpha_mode != AlphaMode::Opaque && m.alpha_map != kNoTexture &&
        a.textures[m.alpha_map].kind != TextureKind::Image)
      return at("materials", i) + "alpha map " + std::to_string(m.alpha_map) + " is not an image";
  }
  return "";
}

std::string textures_violation(const SceneArrays& a) {
  for (size_t i = 0; i < a.textures.size(); ++i) {
    const Texture& t = a.textures[i];
    if (static_cast<uint32_t>(t.kind) > static_cast<uint32_t>(TextureKind::Checker) ||
        static_cast<uint32_t>(t.wrap_u) > static_cast<uint32_t>(TextureWrap::Mirror) ||
        static_cast<uint32_t>(t.wrap_v) > static_cast<uint32_t>(TextureWrap::Mirror))
      return at("textures", i) + "kind or wrap out of range";
    if (t.kind != TextureKind::Image) continue;
    constexpr uint32_t kMaxSide = 1u << 24;  // texel_at's coordinates are ints
    const uint64_t floats = 3ull * t.width * t.height;
    if (t.width < 1 || t.height < 1 || t.width > kMaxSide || t.height > kMaxSide || t.offset + floats > a.texels.size())
      return at("textures", i) + std::to_string(t.width) + " x " + std::to_string(t.height) + " texels at " +
             std::to_string(t.offset) + " lie outside the " + std::to_string(a.texels.size()) + " texel floats";
  }
  return "";
}

// The binary tree (bvh, lbvh) from its root: children and leaves inside the arrays, each
// node reached once, no interior node below more than kBinaryInteriorAbove others.
std::string bvh_violation(const SceneArrays& a) {
  const std::vector<BvhNode>& nodes = a.bvh_nodes;
  if (nodes.empty()) return "";
  std::vector<uint8_t> reached(nodes.size(), 0);
  std::vector<std::pair<uint32_t, uint32_t>> stack = {{0u, 0u}};  // node, interior nodes above
  while (!stack.empty()) {
    const auto [n, above] = stack.back();
    stack.pop_back();
    if (reached[n]) return at("bvh_nodes", n) + "reached twice from the root";
    reached[n] = 1;
    const BvhNode& node = nodes[n];
    if (node.count > 0) {
      if (uint64_t{node.first} + node.count > a.bounded.size())
        return at("bvh_nodes", n) + "leaf primitives [" + std::to_string(node.first) + ", +" +
               std::to_string(node.count) + ") lie outside the " + std::to_string(a.bounded.size()) + " bounded ones";
      continue;
    }
    if (uint64_t{node.first} + 2 > nodes.size())
      return at("bvh_nodes", n) + "children " + of(node.first, nodes.size(), "nodes");
    if (above > kBinaryInteriorAbove)
      return at("bvh_nodes", n) + "deeper than a walk's stack (" + std::to_string(kBinaryInteriorAbove) + ")";
    stack.push_back({node.first + 1, above + 1});
    stack.push_back({node.first, above + 1});
  }
  return "";
}

// A wide node's slot that every ray misses (the builder's unused slots): its box inverted to
// lo = +inf, hi = -inf on every axis.
bool unused_slot(const WideBvhNode& n, int i) {
  for (int axis = 0; axis < 3; ++axis)
    if (!(n.lo[axis][i] == INFINITY && n.hi[axis][i] == -INFINITY)) return false;
  return true;
}

// bvh's 8-wide tree and its leaves' blocks, as bvh_violation.
std::string wide_violation(const SceneArrays& a) {
  for (size_t i = 0; i < a.triangle_blocks.size(); ++i) {
    const TriangleBlock& b = a.triangle_blocks[i];
    if ((b.triangle_lanes | b.other_lanes) > 0xfu || (b.triangle_lanes & b.other_lanes) != 0u)
      return at("triangle_blocks", i) + "lanes out of range";
    for (int l = 0; l < kBlockLanes; ++l) {
      if (((b.triangle_lanes | b.other_lanes) >> l & 1u) && b.id[l] >= a.primitives.size())
        return at("triangle_blocks", i) + "primitive " + of(b.id[l], a.primitives.size(), "primitives");
      if ((b.other_lanes >> l & 1u) && a.primitives[b.id[l]].kind == ShapeKind::Plane)
        return at("triangle_blocks", i) + "primitive " + std::to_string(b.id[l]) +
               " is a plane, which no structure holds";
    }
  }
  const std::vector<WideBvhNode>& nodes = a.wide_nodes;
  if (nodes.empty()) return "";
  std::vector<uint8_t> reached(nodes.size(), 0);
  std::vector<std::pair<uint32_t, uint32_t>> stack = {{0u, 0u}};
  while (!stack.empty()) {
    const auto [n, above] = stack.back();
    stack.pop_back();
    if (reached[n]) return at("wide_nodes", n) + "reached twice from the root";
    reached[n] = 1;
    if (above > kWideInteriorAbove)
      return at("wide_nodes", n) + "deeper than a walk's stack (" + std::to_string(kWideInteriorAbove) + ")";
    for (int i = 0; i < kWideBvhWidth; ++i) {
      const WideBvhNode& node = nodes[n];
      if (unused_slot(node, i)) continue;
      if (node.leaf_blocks[i] > 0) {
        if (uint64_t{node.child[i]} + node.leaf_blocks[i] > a.triangle_blocks.size())
          return at("wide_nodes", n) + "leaf blocks " + of(node.child[i], a.triangle_blocks.size(), "blocks");
      } else if (node.child[i] >= nodes.size()) {
        return at("wide_nodes", n) + "child " + of(node.child[i], nodes.size(), "nodes");
      } else {
        stack.push_back({node.child[i], above + 1});
      }
    }
  }
  return "";
}

// The kd-tree from its root (its walk has no stack, but a cycle would never end), its
// leaves inside kd_prims; the grid's cells inside grid_prims.
std::string kd_and_grid_violation(const SceneArrays& a) {
  if (!a.kd_nodes.empty()) {
    std::vector<uint8_t> reached(a.kd_nodes.size(), 0);
    std::vector<uint32_t> stack = {0u};
    while (!stack.empty()) {
      const uint32_t n = stack.back();
      stack.pop_back();
      if (reached[n]) return at("kd_nodes", n) + "reached twice from the root";
      reached[n] = 1;
      const KdNode& node = a.kd_nodes[n];
      if (node.axis > kKdLeaf) return at("kd_nodes", n) + "axis " + std::to_string(node.axis);
      if (node.axis == kKdLeaf) {
        if (uint64_t{node.a} + node.b > a.kd_prims.size())
          return at("kd_nodes", n) + "leaf primitives lie outside the " + std::to_string(a.kd_prims.size());
      } else if (node.a >= a.kd_nodes.size() || node.b >= a.kd_nodes.size()) {
        return at("kd_nodes", n) + "children outside the " + std::to_string(a.kd_nodes.size()) + " nodes";
      } else {
        stack.push_back(node.b);
        stack.push_back(node.a);
      }
    }
  }
  for (size_t c = 0; c < a.grid_cell_start.size(); ++c)
    if (a.grid_cell_start[c] > a.grid_prims.size() || (c > 0 && a.grid_cell_start[c] < a.grid_cell_start[c - 1]))
      return at("grid_cell_start", c) + std::to_string(a.grid_cell_start[c]) +
             " is not a non-decreasing start inside the " + std::to_string(a.grid_prims.size()) + " grid entries";
  return "";
}

std::string lights_violation(const SceneArrays& a, const SceneView& v) {
  const auto& table = a.light_table;
  for (size_t i = 0; i < table.size(); ++i) {
    const LightEntry& e = table[i];
    switch (e.kind) {
      case LightKind::Point:
      case LightKind::Spot:
      case LightKind::Directional:
        if (e.index >= a.lights.size()) return at("light_table", i) + "light " + of(e.index, a.lights.size(), "lights");
        break;
      case LightKind::Shape:
        if (e.index >= a.primitives.size())
          return at("light_table", i) + "primitive " + of(e.index, a.primitives.size(), "primitives");
        break;
      case LightKind::Environment:
        if (a.sky_cells.empty()) return at("light_table", i) + "the environment, but the bundle has no sky cells";
        break;
      default: return at("light_table", i) + "kind " + std::to_string(static_cast<uint32_t>(e.kind));
    }
  }
  if (a.light_of_prim.size() != a.primitives.size())
    return "light_of_prim: " + std::to_string(a.light_of_prim.size()) + " entries for " +
           std::to_string(a.primitives.size()) + " primitives";
  for (size_t i = 0; i < a.light_of_prim.size(); ++i)
    if (a.light_of_prim[i] != kNoHit && a.light_of_prim[i] >= table.size())
      return at("light_of_prim", i) + "entry " + of(a.light_of_prim[i], table.size(), "light table entries");
  if (v.environment_light != kNoHit &&
      (v.environment_light >= table.size() || table[v.environment_light].kind != LightKind::Environment))
    return "environment_light: entry " + std::to_string(v.environment_light) + " is not the environment's";
  return "";
}

std::string background_violation(const SceneArrays& a, const SceneView& v) {
  const auto image = [&](uint32_t t) { return t < a.textures.size() && a.textures[t].kind == TextureKind::Image; };
  if (v.background.kind == BackgroundKind::Environment && !image(v.background.map))
    return "background: map " + std::to_string(v.background.map) + " is not one of the " +
           std::to_string(a.textures.size()) + " textures' images";
  if (v.background.kind == BackgroundKind::Cubemap)
    for (const uint32_t face : v.background.faces)
      if (!image(face))
        return "background: cube face " + std::to_string(face) + " is not one of the " +
               std::to_string(a.textures.size()) + " textures' images";
  return "";
}

}  // namespace

std::string bundle_reference_violation(const SceneArrays& a, const SceneView& v) {
  for (size_t i = 0; i < a.primitives.size(); ++i) {
    const Primitive& p = a.primitives[i];
    if (static_cast<uint32_t>(p.kind) > static_cast<uint32_t>(ShapeKind::Quad))
      return at("primitives", i) + "kind " + std::to_string(static_cast<uint32_t>(p.kind));
    if (p.material >= a.materials.size())
      return at("primitives", i) + "material " + of(p.material, a.materials.size(), "materials");
    if (p.shading < -1 || (p.shading >= 0 && static_cast<size_t>(p.shading) >= a.triangle_shading.size()))
      return at("primitives", i) + "shading " +
             of(static_cast<uint64_t>(p.shading), a.triangle_shading.size(), "triangles' shading records");
  }
  for (const std::string& problem :
       {bounded_ids("bounded", a.bounded, a.primitives), primitive_ids("unbounded", a.unbounded, a.primitives.size()),
        bounded_ids("kd_prims", a.kd_prims, a.primitives), bounded_ids("grid_prims", a.grid_prims, a.primitives),
        primitive_ids("mirror_prims", a.mirror_prims, a.primitives.size()), materials_violation(a),
        textures_violation(a), bvh_violation(a), wide_violation(a), kd_and_grid_violation(a), lights_violation(a, v),
        background_violation(a, v)})
    if (!problem.empty()) return problem;
  return "";
}

}  // namespace tracer
