#include "accel/bvh_builder.h"

#include <emmintrin.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>

#include "accel/huge_pages.h"

namespace tracer {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;
constexpr int kMaxBuildDepth = 60;  // traversal stacks hold 64 entries
// Ranges of at least task_items(n) items build their halves as OpenMP tasks: about 32 task
// ranges per build, of 2^10 to 2^15 items, in a build of at least kParallelBuildItems.
constexpr uint32_t kMinTaskItems = 1u << 10, kMaxTaskItems = 1u << 15;
uint32_t task_items(uint32_t n) { return std::clamp(n / 32, kMinTaskItems, kMaxTaskItems); }
constexpr uint32_t kTaskNodes = 1u << 14;  // subtrees at least this large are numbered as OpenMP tasks
// Work over many items is split into chunks of kChunkItems fixed by the items alone, each
// chunk's result combined in chunk order: the same result for any thread count.
constexpr uint32_t kChunkItems = 1u << 16;
constexpr uint32_t kParallelBinItems = 1u << 18;  // ranges at least this large are binned in chunks

// One primitive in 32 bytes, as Embree's PrimRef: its box in SSE lanes x, y, z; lane 3 of `lo`
// holds the primitive's id (bits), lane 3 of `hi` is 0, so lo + hi masked to
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
  // The bin coordinate per axis, clamped to [0, count - 1] (a NaN lane to 0); its integer part is the bin.
  __m128 position(__m128 c) const {
    const __m128 f = _mm_mul_ps(_mm_sub_ps(c, lo), scale);
    return _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(static_cast<float>(count - 1)));
  }
  __m128i bins(__m128 c) const { return _mm_cvttps_epi32(position(c)); }
};

struct Split {
  int axis = -1;  // -1: no axis separates the centroids
  int bin = 0;    // items in bins below `bin` go left
  float cost = kInfinity;
};

// Half the surface areas of three boxes, from their extents d0, d1, d2 (lanes x, y, z), in
// lanes 0, 1, 2: the same products and sums as Box::half_area, three at once.
__m128 half_areas(__m128 d0, __m128 d1, __m128 d2) {
  __m128 d3 = _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(d0, d1, d2, d3);  // d0: the three x extents, d1: y, d2: z
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(d0, d1), _mm_mul_ps(d1, d2)), _mm_mul_ps(d2, d0));
}

// Per axis and bin: the box of the refs whose centroids fall in it, and their count (lane
// `axis` of refs[bin]), so that a sweep handles the three axes in one SIMD step.
struct Bins {
  int count;  // bins per axis in use
  __m128 lo[3][kBins], hi[3][kBins];
  alignas(16) int32_t refs[kBins][4];

  explicit Bins(int bins) : count(bins) {
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < count; ++b) lo[axis][b] = Box{}.lo, hi[axis][b] = Box{}.hi;
    for (int b = 0; b < count; ++b) _mm_store_si128(reinterpret_cast<__m128i*>(refs[b]), _mm_setzero_si128());
  }

  void add(const Ref& r, const Binner& binner) {
    alignas(16) int32_t bin[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bin), binner.bins(twice_centroid(r)));
    for (int axis = 0; axis < 3; ++axis) {
      const int b = bin[axis];
      lo[axis][b] = _mm_min_ps(lo[axis][b], r.lo);
      hi[axis][b] = _mm_max_ps(hi[axis][b], r.hi);
      ++refs[b][axis];
    }
  }

  void add(const Bins& other) {
    for (int axis = 0; axis < 3; ++axis)
      for (int b = 0; b < count; ++b) {
        lo[axis][b] = _mm_min_ps(lo[axis][b], other.lo[axis][b]);
        hi[axis][b] = _mm_max_ps(hi[axis][b], other.hi[axis][b]);
        refs[b][axis] += other.refs[b][axis];
      }
  }

  // The split at a bin boundary with the least SAH cost, left and right swept once each, the
  // three axes in the lanes of one vector. The first bin of the least cost on each axis, then
  // the first axis of the least of those: a split needs refs on both sides.
  Split cheapest_split() const {
    __m128 right_area[kBins];
    __m128i right_count[kBins];
    Box acc[3];
    __m128i n = _mm_setzero_si128();
    const auto extents = [&](int axis) { return _mm_max_ps(_mm_sub_ps(acc[axis].hi, acc[axis].lo), _mm_setzero_ps()); };
    for (int b = count - 1; b > 0; --b) {
      for (int axis = 0; axis < 3; ++axis) acc[axis].grow(lo[axis][b], hi[axis][b]);
      n = _mm_add_epi32(n, _mm_load_si128(reinterpret_cast<const __m128i*>(refs[b])));
      right_area[b] = half_areas(extents(0), extents(1), extents(2));
      right_count[b] = n;
    }
    for (Box& box : acc) box = Box{};
    n = _mm_setzero_si128();
    __m128 best_cost = _mm_set1_ps(kInfinity);
    __m128i best_bin = _mm_setzero_si128();
    for (int split = 1; split < count; ++split) {
      for (int axis = 0; axis < 3; ++axis) acc[axis].grow(lo[axis][split - 1], hi[axis][split - 1]);
      n = _mm_add_epi32(n, _mm_load_si128(reinterpret_cast<const __m128i*>(refs[split - 1])));
      const __m128 cost = _mm_add_ps(_mm_mul_ps(half_areas(extents(0), extents(1), extents(2)), _mm_cvtepi32_ps(n)),
                                     _mm_mul_ps(right_area[split], _mm_cvtepi32_ps(right_count[split])));
      const __m128i empty = _mm_or_si128(_mm_cmpeq_epi32(n, _mm_setzero_si128()),
                                         _mm_cmpeq_epi32(right_count[split], _mm_setzero_si128()));
      const __m128 better = _mm_andnot_ps(_mm_castsi128_ps(empty), _mm_cmplt_ps(cost, best_cost));
      best_cost = _mm_or_ps(_mm_and_ps(better, cost), _mm_andnot_ps(better, best_cost));
      best_bin = _mm_or_si128(_mm_and_si128(_mm_castps_si128(better), _mm_set1_epi32(split)),
                              _mm_andnot_si128(_mm_castps_si128(better), best_bin));
    }
    alignas(16) float costs[4];
    alignas(16) int32_t bins[4];
    _mm_store_ps(costs, best_cost);
    _mm_store_si128(reinterpret_cast<__m128i*>(bins), best_bin);
    Split best;
    for (int axis = 0; axis < 3; ++axis)
      if (costs[axis] < best.cost) best = {axis, bins[axis], costs[axis]};
    return best;
  }
};

// Slots [next, end) taken by one thread's subtree and not yet handed out, and how many more it
// may take: a subtree over m items makes at most 2m - 2 nodes below its root.
struct SlotBlock {
  uint32_t next = 0, end = 0;
  size_t may_take = 0;
};

// A range of refs with its box and its centroids' box (both known before it is visited).
struct Range {
  uint32_t begin, end;
  Box bounds, centroids;
};

// Nodes are first written to slots in the order the build makes them: a node over at least
// task_items(n) items takes its children's pair from a shared counter, and a smaller subtree (one
// thread builds it) takes blocks of up to kSlotBlock slots from it, never more in all than it
// can use, and hands out pairs from its block,
// so the slots touched (and faulted in) are about the nodes made. Then the used slots are
// numbered in depth-first order, both children of a node before the first's subtree, so the
// nodes and their order do not depend on which thread built what.
class BvhBuilder {
 public:
  static constexpr uint32_t kSlotBlock = 1024;
  // The root's slot, a pair per node over at least task_items(n) items (fewer than n of them)
  // and at most 2m - 2 slots per one-thread subtree over m items (their ranges are disjoint):
  // under 4n. Only the slots handed out are touched, so the rest costs no memory.
  static size_t slot_capacity(uint32_t n) { return 4 * size_t{n}; }

  BvhBuilder(Ref* refs, uint32_t n, BvhNode* slots, uint32_t* subtree_nodes)
      : refs_(refs),
        task_items_(task_items(n)),
        parallel_(n >= kParallelBuildItems),
        capacity_(slot_capacity(n)),
        slots_(slots),
        subtree_nodes_(subtree_nodes) {}

  // Builds the subtree over `range` into `slot` and slots it takes; returns its node count.
  // `block` is the slot block of the one-thread subtree this node is in (null above them).
  uint32_t build(uint32_t slot, const Range& range, int depth, SlotBlock* block) {
    SlotBlock own;
    const bool tasks = range.end - range.begin >= task_items_;
    if (!tasks && !block) {
      own.may_take = 2 * size_t{range.end - range.begin} - 2;
      block = &own;
    }
    Range left, right;
    BvhNode& node = slots_[slot];
    uint32_t nodes = 1;
    if (split_or_leaf(node, range, depth, left, right)) {
      const uint32_t below = take_pair(block);
      node.first = below;
      node.count = 0;
      uint32_t left_nodes = 0, right_nodes = 0;
      if (tasks) {
#pragma omp task shared(left_nodes) firstprivate(below, left, depth)
        left_nodes = build(below, left, depth + 1, nullptr);
        right_nodes = build(below + 1, right, depth + 1, nullptr);
#pragma omp taskwait
      } else {
        left_nodes = build(below, left, depth + 1, block);
        right_nodes = build(below + 1, right, depth + 1, block);
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
#pragma omp parallel if (parallel_ && total >= kTaskNodes)
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

  // Refs in bins below split.bin first, the others after (Hoare's two-pointer partition: runs
  // already on their side are skipped from both ends, then the two refs that stopped the runs
  // swap); each side's boxes grow in registers on the way.
  void partition(const Range& range, const Binner& binner, const Split& split, Range& left, Range& right) {
    const int axis_bit = 1 << split.axis;
    const __m128 split_bin = _mm_set1_ps(static_cast<float>(split.bin));
    const auto goes_left = [&](__m128 c) {
      return (_mm_movemask_ps(_mm_cmplt_ps(binner.position(c), split_bin)) & axis_bit) != 0;
    };
    Box left_bounds, left_centroids, right_bounds, right_centroids;
    uint32_t i = range.begin, j = range.end;
    while (true) {
      for (; i < j; ++i) {
        const Ref& r = refs_[i];
        const __m128 c = twice_centroid(r);
        if (!goes_left(c)) break;
        left_bounds.grow(r.lo, r.hi);
        left_centroids.grow(c);
      }
      for (; i < j; --j) {
        const Ref& r = refs_[j - 1];
        const __m128 c = twice_centroid(r);
        if (goes_left(c)) break;
        right_bounds.grow(r.lo, r.hi);
        right_centroids.grow(c);
      }
      if (i == j) break;
      std::swap(refs_[i], refs_[j - 1]);  // refs_[i] went right, refs_[j - 1] left
      left_bounds.grow(refs_[i].lo, refs_[i].hi);
      left_centroids.grow(twice_centroid(refs_[i]));
      right_bounds.grow(refs_[j - 1].lo, refs_[j - 1].hi);
      right_centroids.grow(twice_centroid(refs_[j - 1]));
      ++i, --j;
    }
    left = {range.begin, i, left_bounds, left_centroids};
    right = {i, range.end, right_bounds, right_centroids};
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

  uint32_t take_pair(SlotBlock* block) {
    if (!block) return checked(next_slot_.fetch_add(2, std::memory_order_relaxed), 2);
    if (block->next == block->end) {  // may_take stays even and above 0 while pairs are wanted
      const uint32_t size = static_cast<uint32_t>(std::min<size_t>(kSlotBlock, block->may_take));
      block->may_take -= size;
      block->next = checked(next_slot_.fetch_add(size, std::memory_order_relaxed), size);
      block->end = block->next + size;
    }
    const uint32_t pair = block->next;
    block->next += 2;
    return pair;
  }

  // `first` .. `first + size` inside the slot array, which slot_capacity's bound promises.
  uint32_t checked(uint32_t first, uint32_t size) const {
    if (first + size_t{size} > capacity_) throw std::logic_error("the SAH build took more slots than it reserved");
    return first;
  }

  Ref* refs_;
  const uint32_t task_items_;
  const bool parallel_;  // at least kParallelBuildItems items
  const size_t capacity_;
  std::atomic<uint32_t> next_slot_{1};  // slot 0 is the root's
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

uint32_t ref_id(const Ref& r) {
  uint32_t id;
  const float lane = _mm_cvtss_f32(_mm_shuffle_ps(r.lo, r.lo, _MM_SHUFFLE(3, 3, 3, 3)));
  std::memcpy(&id, &lane, sizeof id);
  return id;
}

}  // namespace

std::vector<BvhNode> build_sah_bvh(std::span<const Primitive> primitives, std::vector<uint32_t>& leaf_ids) {
  leaf_ids.clear();
  const uint32_t total = static_cast<uint32_t>(primitives.size());
  const uint32_t chunks = (total + kChunkItems - 1) / kChunkItems;
  // Each chunk of primitives writes its bounded ones' refs from its own first position; where
  // planes left gaps the chunks move down after, in order.
  const auto refs = allocate_on_huge_pages<Ref>(std::max<size_t>(total, 1));
  std::vector<Range> chunk_ranges(chunks);
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (int64_t c = 0; c < static_cast<int64_t>(chunks); ++c) {
    Range& chunk = chunk_ranges[static_cast<size_t>(c)];
    chunk.begin = chunk.end = static_cast<uint32_t>(c) * kChunkItems;
    for (uint32_t id = chunk.begin; id < std::min(total, chunk.begin + kChunkItems); ++id) {
      if (primitives[id].kind == ShapeKind::Plane) continue;  // unbounded: never in the BVH
      const Bounds b = primitive_bounds(primitives[id]);
      float id_bits;
      std::memcpy(&id_bits, &id, sizeof id_bits);
      const Ref r = {_mm_setr_ps(b.lo.x, b.lo.y, b.lo.z, id_bits), _mm_setr_ps(b.hi.x, b.hi.y, b.hi.z, 0.0f)};
      refs.get()[chunk.end++] = r;
      chunk.bounds.grow(r.lo, r.hi);
      chunk.centroids.grow(twice_centroid(r));
    }
  }
  Range root{0, 0, {}, {}};
  for (const Range& chunk : chunk_ranges) {
    if (chunk.begin != root.end)
      std::memmove(refs.get() + root.end, refs.get() + chunk.begin, (chunk.end - chunk.begin) * sizeof(Ref));
    root.end += chunk.end - chunk.begin;
    root.bounds.grow(chunk.bounds), root.centroids.grow(chunk.centroids);
  }
  const uint32_t n = root.end;
  if (n == 0) return {};
  const size_t slot_count = BvhBuilder::slot_capacity(n);  // BvhNode is an aggregate: malloc'd storage holds nodes
  const auto slots = allocate_on_huge_pages<BvhNode>(slot_count);
  const auto subtree_nodes = allocate_on_huge_pages<uint32_t>(slot_count);
  BvhBuilder builder(refs.get(), n, slots.get(), subtree_nodes.get());
#pragma omp parallel if (n >= kParallelBuildItems)
#pragma omp single
  builder.build(0, root, 0, nullptr);
  std::vector<BvhNode> nodes = builder.numbered();
  reserve_on_huge_pages(leaf_ids, n);
  leaf_ids.resize(n);
#pragma omp parallel for schedule(static) if (n >= kChunkItems)
  for (int64_t i = 0; i < static_cast<int64_t>(n); ++i) leaf_ids[static_cast<size_t>(i)] = ref_id(refs.get()[i]);
  return nodes;
}

}  // namespace tracer
