#include "accel/bvh_pairs_builder.h"

#include "io/input_error.h"

namespace tracer {

namespace {

[[noreturn]] void refuse(const std::string& source, const std::string& what) {
  throw InputError(source + ": bvh_nodes: " + what);
}

// The interior nodes in depth-first order from the root, the left child first: the records'
// order, so a walk reads neighbours.
// A walk pushes at most one entry per interior node above the one it visits, so a tree whose
// paths hold at most kBvhPairStackSize interior nodes fits its stack.
std::vector<uint32_t> interior_in_walk_order(const std::vector<BvhNode>& binary, const std::string& source) {
  std::vector<uint32_t> order;
  std::vector<uint8_t> reached(binary.size(), 0);
  struct Visit {
    uint32_t node, interior_above;
  };
  std::vector<Visit> stack = {{0, 0}};
  while (!stack.empty()) {
    const auto [n, above] = stack.back();
    stack.pop_back();
    if (reached[n]) refuse(source, "node " + std::to_string(n) + " is reached twice");
    reached[n] = 1;
    if (binary[n].count > 0) continue;
    const uint32_t first = binary[n].first;
    if (first >= binary.size() || binary.size() - first < 2)
      refuse(source,
             "node " + std::to_string(n) + "'s children lie outside the " + std::to_string(binary.size()) + " nodes");
    if (above == kBvhPairStackSize)
      refuse(source, "node " + std::to_string(n) + " lies below " + std::to_string(kBvhPairStackSize) +
                         " interior nodes, deeper than a walk's stack (the builders stop at depth 62)");
    order.push_back(n);
    stack.push_back({first + 1, above + 1});
    stack.push_back({first, above + 1});
  }
  return order;
}

}  // namespace

BvhPairs build_bvh_pairs(const std::vector<BvhNode>& binary, const std::vector<uint32_t>& leaf_order,
                         const std::vector<Primitive>& primitives, const std::string& source) {
  if (binary.empty() || binary[0].count > 0) return {};
  const std::vector<uint32_t> order = interior_in_walk_order(binary, source);
  std::vector<int32_t> pair_of(binary.size(), -1);
  for (size_t i = 0; i < order.size(); ++i) pair_of[order[i]] = static_cast<int32_t>(i);

  BvhPairs out;
  out.nodes.reserve(order.size());
  out.triangles.reserve(leaf_order.size());
  // A child's reference; a leaf's triangles are appended here. False: a leaf holds another shape.
  auto reference = [&](uint32_t child, int32_t& ref) {
    const BvhNode& c = binary[child];
    if (c.count == 0) {
      ref = pair_of[child];
      return true;
    }
    if (c.first > leaf_order.size() || leaf_order.size() - c.first < c.count)
      refuse(source, "leaf " + std::to_string(child) + "'s primitives lie outside the " +
                         std::to_string(leaf_order.size()) + " bounded ones");
    ref = ~static_cast<int32_t>(out.triangles.size());
    for (uint32_t i = c.first; i < c.first + c.count; ++i) {
      const uint32_t id = leaf_order[i];
      if (id >= primitives.size())
        refuse(source, "bounded[" + std::to_string(i) + "] = " + std::to_string(id) + " is not one of the " +
                           std::to_string(primitives.size()) + " primitives");
      const Primitive& p = primitives[id];
      if (p.kind != ShapeKind::Triangle) return false;
      out.triangles.push_back({p.a, id, p.b, i + 1 == c.first + c.count ? 1u : 0u, p.c, 0u});
    }
    return true;
  };
  for (const uint32_t n : order) {
    const BvhNode& l = binary[binary[n].first];
    const BvhNode& r = binary[binary[n].first + 1];
    BvhPairNode pair = {l.lo, 0, l.hi, 0, r.lo, 0u, r.hi, 0u};
    if (!reference(binary[n].first, pair.ref0) || !reference(binary[n].first + 1, pair.ref1)) return {};
    out.nodes.push_back(pair);
  }
  return out;
}

}  // namespace tracer
