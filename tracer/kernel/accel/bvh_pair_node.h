// The binary BVH as the GPU's walk reads it (Aila and Laine, "Understanding the Efficiency of
// Ray Traversal on GPUs", HPG 2009): one 64-byte record per interior node holding both
// children's boxes and references, read as four 16-byte loads through the read-only data
// path, and the leaves' triangles copied in leaf order, 48 bytes each, three loads and no
// indirection. Built from the binary tree on the host (tracer/accel/bvh_pairs_builder.h) for
// a scene whose bounded primitives are all triangles; the boxes are the tree's, bit for bit.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

// A child reference: >= 0 an interior node's pair, < 0 ~(its leaf's first triangle slot).
struct alignas(16) BvhPairNode {
  Vec3 lo0;
  int32_t ref0;
  Vec3 hi0;
  int32_t ref1;
  Vec3 lo1;
  uint32_t unused0;
  Vec3 hi1;
  uint32_t unused1;
};
static_assert(sizeof(BvhPairNode) == 64, "four 16-byte loads");

// One triangle of a leaf: its vertices, its primitive id, and whether it ends its leaf.
struct alignas(16) PairTriangle {
  Vec3 a;
  uint32_t id;
  Vec3 b;
  uint32_t last;  // 1 on a leaf's last triangle
  Vec3 c;
  uint32_t unused;
};
static_assert(sizeof(PairTriangle) == 48, "three 16-byte loads");

#if defined(__CUDA_ARCH__)
// Four 16-byte loads through the read-only (non-coherent) cache: the records never change
// while a kernel runs.
template <class T, int kQuads = sizeof(T) / 16>
__device__ __forceinline__ T load_read_only(const T* p) {
  T out;
  const float4* from = reinterpret_cast<const float4*>(p);
  float4* to = reinterpret_cast<float4*>(&out);
#pragma unroll
  for (int i = 0; i < kQuads; ++i) to[i] = __ldg(from + i);
  return out;
}
#else
template <class T>
inline T load_read_only(const T* p) {
  return *p;
}
#endif

}  // namespace tracer
