// The primitives of one TriangleBlock against a ray. The watertight test's first steps, the
// three edge functions of Woop et al. 2013 and, where a lane's signs agree, its distance t,
// run for the 4 triangles in SIMD lanes with the scalar test's operations in its order (no
// FMA), and only the lanes they cannot reject (an edge function of 0, or all three of one sign
// and t in (0, tmax]) go on to the scalar test, which computes them again and decides. A lane
// rejected here is one the scalar test rejects at the same step, so the hits are the scalar
// test's, bit for bit.
#pragma once
#include "kernel/accel/primitive_hit.h"
#include "kernel/accel/wide_box_test.h"

namespace tracer {

TRACER_HD int lowest_set_bit(uint32_t bits) {
#if defined(__CUDA_ARCH__)
  return __ffs(bits) - 1;
#else
  return __builtin_ctz(bits);
#endif
}

// Lanes of `triangle_lanes` whose watertight edge functions and distance do not rule out a hit
// with t in (0, tmax].
TRACER_HD uint32_t watertight_candidates(const TriangleBlock& b, const WideRayQuery& q, float tmax) {
#if defined(TRACER_X86_LANES)
  const int kx = q.k[0], ky = q.k[1], kz = q.k[2];
  const __m128 ox = _mm_set1_ps(q.origin[kx]), oy = _mm_set1_ps(q.origin[ky]), oz = _mm_set1_ps(q.origin[kz]);
  const __m128 sx = _mm_set1_ps(q.sx), sy = _mm_set1_ps(q.sy);
  __m128 x[3], y[3], z[3];
  for (int v = 0; v < 3; ++v) {  // x' = (v_kx - o_kx) - sx (v_kz - o_kz), as intersect_triangle
    const __m128 dz = _mm_sub_ps(_mm_load_ps(b.v[v][kz]), oz);
    x[v] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(b.v[v][kx]), ox), _mm_mul_ps(sx, dz));
    y[v] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(b.v[v][ky]), oy), _mm_mul_ps(sy, dz));
    z[v] = _mm_mul_ps(_mm_set1_ps(q.sz), dz);
  }
  const __m128 u = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
  const __m128 v = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
  const __m128 w = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
  const __m128 zero = _mm_setzero_ps();
  const __m128 any_zero = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_cmpeq_ps(v, zero)), _mm_cmpeq_ps(w, zero));
  const __m128 any_negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(u, zero), _mm_cmplt_ps(v, zero)), _mm_cmplt_ps(w, zero));
  const __m128 any_positive = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_cmpgt_ps(v, zero)), _mm_cmpgt_ps(w, zero));
  const uint32_t recompute = static_cast<uint32_t>(_mm_movemask_ps(any_zero));
  const uint32_t signs_agree = ~static_cast<uint32_t>(_mm_movemask_ps(_mm_and_ps(any_negative, any_positive))) & 0xfu;
  if ((b.triangle_lanes & signs_agree & ~recompute) == 0u) return b.triangle_lanes & recompute;
  // t = (u z0 + v z1 + w z2) / (u + v + w) outside (0, tmax] (det = 0 among them): rejected by
  // the scalar test too, whose tmax (the best hit so far) can only be smaller when it tests the lane
  const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
  const __m128 t =
      _mm_div_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(u, z[0]), _mm_mul_ps(v, z[1])), _mm_mul_ps(w, z[2])), det);
  const __m128 in_range = _mm_and_ps(_mm_cmpgt_ps(t, zero), _mm_cmple_ps(t, _mm_set1_ps(tmax)));
  const uint32_t in_range_lanes = static_cast<uint32_t>(_mm_movemask_ps(in_range));
  return b.triangle_lanes & (recompute | (signs_agree & in_range_lanes));
#else
  (void)q, (void)tmax;
  return b.triangle_lanes;
#endif
}

// Tests every primitive of the block, keeping the closest (t, id) in `best`.
template <uint32_t kCode = kTraceAll>
TRACER_HD void test_triangle_block(const SceneView& scene, const TriangleBlock& b, const WideRayQuery& q,
                                   const Ray& ray, const RayShear& shear, Hit& best) {
  for (uint32_t lanes = b.other_lanes; lanes != 0; lanes &= lanes - 1)
    test_primitive<leaf_trace_code<kCode>()>(scene, b.id[lowest_set_bit(lanes)], ray, shear, best);
  if (!traces<kCode>(kFeatureTriangle)) return;
  const bool watertight = tests_watertight<kCode>(scene.settings.triangle_test);
  for (uint32_t lanes = watertight ? watertight_candidates(b, q, best.t) : b.triangle_lanes; lanes != 0;
       lanes &= lanes - 1) {
    const int l = lowest_set_bit(lanes);
    const Vec3 v0 = {b.v[0][0][l], b.v[0][1][l], b.v[0][2][l]};
    const Vec3 v1 = {b.v[1][0][l], b.v[1][1][l], b.v[1][2][l]};
    const Vec3 v2 = {b.v[2][0][l], b.v[2][1][l], b.v[2][2][l]};
    float t = 0.0f, b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
    const bool hit = watertight ? intersect_triangle(v0, v1, v2, ray, shear, 0.0f, best.t, t, b0, b1, b2)
                                : intersect_triangle_moller_trumbore(v0, v1, v2, ray, 0.0f, best.t, t, b0, b1, b2);
    if (hit && alpha_keeps<kCode>(scene, b.id[l], ray, t, b1, b2)) keep_if_closer(best, t, b.id[l], b1, b2);
  }
}

}  // namespace tracer
