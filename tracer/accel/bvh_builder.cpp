#include "accel/bvh_builder.h"

#include <emmintrin.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>

#include "accel/huge_pages.h"

namespace tracer {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;
constexpr int kMaxBuildDepth = 60;         // traversal stacks hold 64 entries
constexpr uint32_t kTaskItems = 1u << 15;  // ranges at least this large build their halves as OpenMP tasks
constexpr uint32_t kTaskNodes = 1u << 14;  // subtrees at least this large are numbered as OpenMP tasks
// Work over many items is split into chunks of kChunkItems fixed by the items alone, each
// chunk's result combined in chunk order: the same result for any thread count.
constexpr uint32_t kChunkItems = 1u << 16;
constexpr uint32_t kParallelBinItems = 1u << 18;  // ranges at least this large are binned in chunks

// One item in 32 bytes, as Embree's PrimRef: its box in SSE lanes x, y, z; lane 3 of `lo`
// holds the item's index in `items` (bits), lane 3 of `hi` is 0, so lo + hi masked to
// x, y, z is twice the centroid.
struct alignas(16) Ref {
  __m128 lo, hi;
};

const __m128 kXyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));

__m128 twice_centroid(const Ref& r) { return _mm_add_ps(_mm_and_ps(r.lo, kXyz), r.hi); }

struct Box {
  __m128 lo = _mm_set1_ps(kInfinity), hi = _mm_set1_ps(-kInfinity);  // empty
  void grow(__m128 l, __m128 h) { lo = _mm_min_ps(lo, l), hi = _mm_max_ps(hi, h); }
  void grow(__m128 p) { grow(p, p); }
  void grow(const Box& b) { grow(b.lo, b.hi); }
  // Half the surface area: the SAH compares areas, so the factor 2 cancels. 0 when empty.
  float half_area() const {
    float d[4];
    _mm_storeu_ps(d, _mm_max_ps(_mm_sub_ps(hi, lo), _mm_setzero_ps()));
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
  }
};

// Maps twice-centroids to `count` bins: bin = floor((c - lo) * scale) per axis, clamped to
// the bins (a NaN lane goes to bin 0). An axis whose centroids coincide has scale 0: all in
// bin 0. A range of n < 16 items uses n bins: a node near the leaves costs what it holds.
struct Binner {
  int count;
  __m128 lo, scale;
  Binner(const Box& centroids, uint32_t items) : count(static_cast<int>(std::min<uint32_t>(items, kBins))) {
    lo = centroids.lo;
    float l[4], h[4], s[4] = {0, 0, 0, 0};
    _mm_storeu_ps(l, centroids.lo);
    _mm_storeu_ps(h, centroids.hi);
    for (int a = 0; a < 3; ++a)
      if (h[a] - l[a] > 0.0f) s[a] = static_cast<float>(count) * 0.99999f / (h[a] - l[a]);
    scale = _mm_loadu_ps(s);
  }
  __m128i bins(__m128 c) const {
    const __m128 f = _mm_mul_ps(_mm_sub_ps(c, lo), scale);
    return _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(static_cast<float>(count - 1))));
  }
};

struct Split {
  int axis = -1;  // -1: no axis separates the centroids
  int bin = 0;    // items in bins below `bin` go left
  float cost = kInfinity;
};

// Per axis and bin: the box of the refs whose centroids fall in it, and their count.
struct Bins {
  int count;  // bins per axis in use
  __m128 lo[3][kBins], hi[3][kBins];
  uint32_t refs[3][kBins];

  explicit Bins(int bins) : count(bins) {
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < count; ++b) lo[axis][b] = Box{}.lo, hi[axis][b] = Box{}.hi, refs[axis][b] = 0;
  }

  void add(const Ref& r, const Binner& binner) {
    alignas(16) int32_t bin[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bin), binner.bins(twice_centroid(r)));
    for (int axis = 0; axis < 3; ++axis) {
      const int b = bin[axis];
      lo[axis][b] = _mm_min_ps(lo[axis][b], r.lo);
      hi[axis][b] = _mm_max_ps(hi[axis][b], r.hi);
      ++refs[axis][b];
    }
  }

  void add(const Bins& other) {
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < count; ++b) {
        lo[axis][b] = _mm_min_ps(lo[axis][b], other.lo[axis][b]);
        hi[axis][b] = _mm_max_ps(hi[axis][b], other.hi[axis][b]);
        refs[axis][b] += other.refs[axis][b];
      }
  }

  // The split at a bin boundary with the least SAH cost, left and right swept once each.
  Split cheapest_split() const {
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      float right_area[kBins];
      uint32_t right_count[kBins];
      Box acc;
      uint32_t n = 0;
      for (int b = count - 1; b > 0; --b) {
        acc.grow(lo[axis][b], hi[axis][b]);
        n += refs[axis][b];
        right_area[b] = acc.half_area();
        right_count[b] = n;
      }
      acc = Box{};
      n = 0;
      for (int split = 1; split < count; ++split) {
        acc.grow(lo[axis][split - 1], hi[axis][split - 1]);
        n += refs[axis][split - 1];
        if (n == 0 || right_count[split] == 0) continue;
        const float cost = acc.half_area() * n + right_area[split] * right_count[split];
        if (cost < best.cost) best = {axis, split, cost};
      }
    }
    return best;
  }
};

// A range of refs with its box and its centroids' box (both known before it is visited).
struct Range {
  uint32_t begin, end;
  Box bounds, centroids;
};

// Nodes are first written to slots fixed by item ranges, so that threads never share a
// counter: the subtree over m items has at most 2m - 1 nodes, its root in the slot its parent
// chose and its other nodes in the 2m - 2 slots from `below`, its children's pair first. Then
// the used slots are numbered in depth-first order, both children of a node before the first's
// subtree, so the nodes and their order do not depend on which thread built what.
class BvhBuilder {
 public:
  BvhBuilder(std::vector<Ref>& refs, BvhNode* slots, uint32_t* subtree_nodes)
      : refs_(refs), slots_(slots), subtree_nodes_(subtree_nodes) {}

  // Builds the subtree over `range` into `slot` and the slots from `below`; returns its node count.
  uint32_t build(uint32_t slot, const Range& range, uint32_t below, int depth) {
    Range left, right;
    BvhNode& node = slots_[slot];
    uint32_t nodes = 1;
    if (split_or_leaf(node, range, depth, left, right)) {
      node.first = below;
      node.count = 0;
      const uint32_t left_below = below + 2, right_below = left_below + 2 * (left.end - left.begin) - 2;
      uint32_t left_nodes = 0, right_nodes = 0;
      if (range.end - range.begin >= kTaskItems) {
#pragma omp task shared(left_nodes) firstprivate(below, left, left_below, depth)
        left_nodes = build(below, left, left_below, depth + 1);
        right_nodes = build(below + 1, right, right_below, depth + 1);
#pragma omp taskwait
      } else {
        left_nodes = build(below, left, left_below, depth + 1);
        right_nodes = build(below + 1, right, right_below, depth + 1);
      }
      nodes += left_nodes + right_nodes;
    }
    subtree_nodes_[slot] = nodes;
    return nodes;
  }

  // The used slots, numbered depth-first. A node's position fixes where its subtree goes (its
  // children at `next` and `next + 1`, the first child's descendants from next + 2, the
  // second's after them), so large subtrees are copied as OpenMP tasks, each into its own
  // positions.
  std::vector<BvhNode> numbered() const {
    const uint32_t total = subtree_nodes_[0];
    std::vector<BvhNode> nodes;
    reserve_on_huge_pages(nodes, total);
    nodes.resize(total);
    nodes[0] = slots_[0];
#pragma omp parallel if (total >= kTaskNodes)
#pragma omp single
    number(nodes.data(), 0, 1);
    return nodes;
  }

 private:
  void number(BvhNode* nodes, uint32_t index, uint32_t next) const {
    if (nodes[index].count != 0) return;
    const uint32_t slot = nodes[index].first, left_nodes = subtree_nodes_[slot];
    nodes[next] = slots_[slot];
    nodes[next + 1] = slots_[slot + 1];
    nodes[index].first = next;
    const uint32_t right_next = next + 1 + left_nodes;  // after the first child's left_nodes - 1 descendants
    if (left_nodes >= kTaskNodes) {
#pragma omp task firstprivate(nodes, next)
      number(nodes, next, next + 2);
      number(nodes, next + 1, right_next);
#pragma omp taskwait
    } else {
      number(nodes, next, next + 2);
      number(nodes, next + 1, right_next);
    }
  }

  // Sets the node's box; makes it a leaf (returns false) or partitions its refs in two.
  bool split_or_leaf(BvhNode& node, const Range& range, int depth, Range& left, Range& right) {
    float lo[4], hi[4];
    _mm_storeu_ps(lo, range.bounds.lo);
    _mm_storeu_ps(hi, range.bounds.hi);
    node.lo = {lo[0], lo[1], lo[2]};
    node.hi = {hi[0], hi[1], hi[2]};
    node.first = range.begin;
    node.count = range.end - range.begin;
    const uint32_t count = range.end - range.begin;
    if (count <= kMaxLeafSize || depth >= kMaxBuildDepth) return false;
    const Binner binner(range.centroids, count);
    const Split split = best_split(range, binner);
    if (split.axis >= 0) {
      // Traversal step costs about as much as one primitive test (a cost of 1 per node).
      const float leaf_cost = range.bounds.half_area() * count;
      if (count <= 2 * kMaxLeafSize && split.cost + range.bounds.half_area() >= leaf_cost) return false;
      partition(range, binner, split, left, right);
    } else {  // all centroids coincide: split the list in half so the build always progresses
      halve(range, left, right);
    }
    return true;
  }

  // The SAH cost of splitting at every bin boundary on every axis, binned in one pass; a large
  // range is binned over fixed chunks as OpenMP tasks, merged in chunk order (a box's min and
  // max and a count do not depend on the order they are taken in).
  Split best_split(const Range& range, const Binner& binner) const {
    Bins bins(binner.count);
    const uint32_t count = range.end - range.begin;
    if (count >= kParallelBinItems) {
      const uint32_t chunks = (count + kChunkItems - 1) / kChunkItems;
      std::vector<Bins> chunk_bins(chunks, bins);
#pragma omp taskloop grainsize(1) shared(chunk_bins)
      for (uint32_t c = 0; c < chunks; ++c) {
        const uint32_t begin = range.begin + c * kChunkItems;
        for (uint32_t i = begin; i < std::min(range.end, begin + kChunkItems); ++i) chunk_bins[c].add(refs_[i], binner);
      }
      for (const Bins& b : chunk_bins) bins.add(b);
    } else {
      for (uint32_t i = range.begin; i < range.end; ++i) bins.add(refs_[i], binner);
    }
    return bins.cheapest_split();
  }

  // Refs in bins below split.bin first, the others after; each side's boxes grown on the way.
  void partition(const Range& range, const Binner& binner, const Split& split, Range& left, Range& right) {
    alignas(16) int32_t bin[4];
    uint32_t i = range.begin, j = range.end;
    left = right = Range{};
    while (i < j) {
      const Ref r = refs_[i];
      const __m128 c = twice_centroid(r);
      _mm_store_si128(reinterpret_cast<__m128i*>(bin), binner.bins(c));
      Range& side = bin[split.axis] < split.bin ? left : right;
      side.bounds.grow(r.lo, r.hi);
      side.centroids.grow(c);
      if (&side == &left) {
        ++i;
      } else {
        refs_[i] = refs_[--j];
        refs_[j] = r;
      }
    }
    left.begin = range.begin, left.end = i;
    right.begin = i, right.end = range.end;
  }

  void halve(const Range& range, Range& left, Range& right) const {
    const uint32_t mid = range.begin + (range.end - range.begin) / 2;
    left = right = Range{};
    left.begin = range.begin, left.end = mid;
    right.begin = mid, right.end = range.end;
    for (Range* side : {&left, &right})
      for (uint32_t i = side->begin; i < side->end; ++i) {
        side->bounds.grow(refs_[i].lo, refs_[i].hi);
        side->centroids.grow(twice_centroid(refs_[i]));
      }
  }

  std::vector<Ref>& refs_;
  BvhNode* slots_;
  uint32_t* subtree_nodes_;  // per used slot: the nodes of its subtree, itself included
};

template <class T>
std::unique_ptr<T, decltype(&std::free)> allocate_on_huge_pages(size_t count) {
  std::unique_ptr<T, decltype(&std::free)> p(static_cast<T*>(std::malloc(count * sizeof(T))), &std::free);
  if (!p) throw std::bad_alloc();
  advise_huge_pages(p.get(), count * sizeof(T));
  return p;
}

uint32_t ref_index(const Ref& r) {
  uint32_t index;
  const float lane = _mm_cvtss_f32(_mm_shuffle_ps(r.lo, r.lo, _MM_SHUFFLE(3, 3, 3, 3)));
  std::memcpy(&index, &lane, sizeof index);
  return index;
}

}  // namespace

std::vector<BvhNode> build_sah_bvh(std::span<const BuildItem> items, std::vector<uint32_t>& leaf_ids) {
  if (items.empty()) return {};
  const uint32_t n = static_cast<uint32_t>(items.size());
  std::vector<Ref> refs;
  reserve_on_huge_pages(refs, n);
  refs.resize(n);
  const uint32_t chunks = (n + kChunkItems - 1) / kChunkItems;
  std::vector<Range> chunk_ranges(chunks);
#pragma omp parallel for schedule(static) if (n >= kTaskItems)
  for (int64_t c = 0; c < static_cast<int64_t>(chunks); ++c) {
    Range& chunk = chunk_ranges[static_cast<size_t>(c)];
    chunk.begin = static_cast<uint32_t>(c) * kChunkItems;
    chunk.end = std::min<uint32_t>(n, chunk.begin + kChunkItems);
    for (uint32_t i = chunk.begin; i < chunk.end; ++i) {
      const Bounds& b = items[i].bounds;
      float index;
      std::memcpy(&index, &i, sizeof index);
      const Ref r = {_mm_setr_ps(b.lo.x, b.lo.y, b.lo.z, index), _mm_setr_ps(b.hi.x, b.hi.y, b.hi.z, 0.0f)};
      refs[i] = r;
      chunk.bounds.grow(r.lo, r.hi);
      chunk.centroids.grow(twice_centroid(r));
    }
  }
  Range root{0, n, {}, {}};
  for (const Range& chunk : chunk_ranges) root.bounds.grow(chunk.bounds), root.centroids.grow(chunk.centroids);
  const size_t slot_count = 2 * size_t{n} - 1;  // BvhNode is an aggregate: malloc'd storage holds nodes
  const auto slots = allocate_on_huge_pages<BvhNode>(slot_count);
  const auto subtree_nodes = allocate_on_huge_pages<uint32_t>(slot_count);
  BvhBuilder builder(refs, slots.get(), subtree_nodes.get());
#pragma omp parallel if (n >= kTaskItems)
#pragma omp single
  builder.build(0, root, 1, 0);
  std::vector<BvhNode> nodes = builder.numbered();
  leaf_ids.clear();
  reserve_on_huge_pages(leaf_ids, n);
  leaf_ids.resize(n);
#pragma omp parallel for schedule(static) if (n >= kTaskItems)
  for (int64_t i = 0; i < static_cast<int64_t>(n); ++i)
    leaf_ids[static_cast<size_t>(i)] = items[ref_index(refs[static_cast<size_t>(i)])].id;
  return nodes;
}

}  // namespace tracer
