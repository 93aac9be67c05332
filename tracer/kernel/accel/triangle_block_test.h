// The primitives of one TriangleBlock against a ray. On x86 the watertight test (Woop et al.
// 2013, kernel/geom/triangle.h) runs for the block's 4 triangles in SIMD lanes, each lane with
// the scalar test's operations in its order (no FMA), so its t and barycentrics are the scalar
// test's bit for bit; only a lane with an edge function of exactly 0 goes through the scalar
// test, which recomputes it in double. Elsewhere (the GPU) every lane takes the scalar test.
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

// The watertight test of kernel/geom/triangle.h for a block's 4 triangles against tmax: `hit`
// holds the lanes it accepts, with their t and barycentrics; `recompute` the lanes with an edge
// function of exactly 0, which the scalar test recomputes in double. Each lane performs the
// scalar test's operations in its order (no FMA), so a lane's values are the scalar test's bit
// for bit. A lane with t in (0, tmax] has finite operands, where SSE's MAXPS(a, b) is
// max_of(a, b) under either NaN rule (kernel/base/platform.h).
#if defined(TRACER_X86_LANES)
struct BlockHits {
  uint32_t hit, recompute;
  float t[kBlockLanes], b1[kBlockLanes], b2[kBlockLanes];
};

inline BlockHits watertight_block_hits(const TriangleBlock& b, const WideRayQuery& q, float tmax) {
  BlockHits h;
  h.hit = 0u;
  const int kx = q.k[0], ky = q.k[1], kz = q.k[2];
  const __m128 ox = _mm_set1_ps(q.origin[kx]), oy = _mm_set1_ps(q.origin[ky]), oz = _mm_set1_ps(q.origin[kz]);
  const __m128 sx = _mm_set1_ps(q.sx), sy = _mm_set1_ps(q.sy);
  __m128 x[3], y[3], dz[3], z[3];
  for (int v = 0; v < 3; ++v) {  // x' = (v_kx - o_kx) - sx (v_kz - o_kz), as intersect_triangle
    dz[v] = _mm_sub_ps(_mm_load_ps(b.v[v][kz]), oz);
    x[v] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(b.v[v][kx]), ox), _mm_mul_ps(sx, dz[v]));
    y[v] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(b.v[v][ky]), oy), _mm_mul_ps(sy, dz[v]));
    z[v] = _mm_mul_ps(_mm_set1_ps(q.sz), dz[v]);
  }
  const __m128 u = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
  const __m128 v = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
  const __m128 w = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
  const __m128 zero = _mm_setzero_ps();
  const __m128 any_zero = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_cmpeq_ps(v, zero)), _mm_cmpeq_ps(w, zero));
  const __m128 any_negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(u, zero), _mm_cmplt_ps(v, zero)), _mm_cmplt_ps(w, zero));
  const __m128 any_positive = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_cmpgt_ps(v, zero)), _mm_cmpgt_ps(w, zero));
  h.recompute = b.triangle_lanes & static_cast<uint32_t>(_mm_movemask_ps(any_zero));
  const uint32_t signs_agree = ~static_cast<uint32_t>(_mm_movemask_ps(_mm_and_ps(any_negative, any_positive))) & 0xfu;
  const uint32_t candidates = b.triangle_lanes & signs_agree & ~h.recompute;
  if (candidates == 0u) return h;
  // t = (u z0 + v z1 + w z2) / (u + v + w) in (0, tmax] (det = 0 fails it)
  const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
  const __m128 t =
      _mm_div_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(u, z[0]), _mm_mul_ps(v, z[1])), _mm_mul_ps(w, z[2])), det);
  const __m128 in_range = _mm_and_ps(_mm_cmpgt_ps(t, zero), _mm_cmple_ps(t, _mm_set1_ps(tmax)));
  const uint32_t in_range_lanes = candidates & static_cast<uint32_t>(_mm_movemask_ps(in_range));
  if (in_range_lanes == 0u) return h;
  // t conservatively above 0: intersect_triangle's bound on t's error, term by term
  const auto add = [](__m128 l, __m128 r) { return _mm_add_ps(l, r); };
  const auto mul = [](__m128 l, __m128 r) { return _mm_mul_ps(l, r); };
  const auto abs = [](__m128 l) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), l); };
  const auto max3 = [&](const __m128* l) { return _mm_max_ps(abs(l[0]), _mm_max_ps(abs(l[1]), abs(l[2]))); };
  const __m128 max_zt = max3(z), max_xt = max3(x), max_yt = max3(y), max_z = max3(dz);
  const __m128 gamma2 = _mm_set1_ps(error_gamma(2)), gamma3 = _mm_set1_ps(error_gamma(3));
  const __m128 gamma5 = _mm_set1_ps(error_gamma(5));
  const __m128 delta_z = mul(gamma3, max_zt);
  const __m128 delta_x = mul(gamma5, add(max_xt, mul(_mm_set1_ps(2.0f * abs_of(q.sx)), max_z)));
  const __m128 delta_y = mul(gamma5, add(max_yt, mul(_mm_set1_ps(2.0f * abs_of(q.sy)), max_z)));
  const __m128 delta_e =
      mul(_mm_set1_ps(2.0f), add(add(mul(mul(gamma2, max_xt), max_yt), mul(delta_y, max_xt)), mul(delta_x, max_yt)));
  const __m128 max_e = _mm_max_ps(abs(u), _mm_max_ps(abs(v), abs(w)));
  const __m128 error = add(add(mul(mul(gamma3, max_e), max_zt), mul(delta_e, max_zt)), mul(delta_z, max_e));
  const __m128 delta_t = _mm_div_ps(mul(_mm_set1_ps(3.0f), error), abs(det));
  h.hit = in_range_lanes & static_cast<uint32_t>(_mm_movemask_ps(_mm_cmpgt_ps(t, delta_t)));
  _mm_storeu_ps(h.t, t);
  _mm_storeu_ps(h.b1, _mm_div_ps(v, det));
  _mm_storeu_ps(h.b2, _mm_div_ps(w, det));
  return h;
}
#endif

// Triangle lane l of the block through the scalar test.
template <uint32_t kCode>
TRACER_HD void test_triangle_lane(const SceneView& scene, const TriangleBlock& b, int l, const Ray& ray,
                                  const RayShear& shear, bool watertight, Hit& best) {
  const Vec3 v0 = {b.v[0][0][l], b.v[0][1][l], b.v[0][2][l]};
  const Vec3 v1 = {b.v[1][0][l], b.v[1][1][l], b.v[1][2][l]};
  const Vec3 v2 = {b.v[2][0][l], b.v[2][1][l], b.v[2][2][l]};
  float t = 0.0f, b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
  const bool hit = watertight ? intersect_triangle(v0, v1, v2, ray, shear, 0.0f, best.t, t, b0, b1, b2)
                              : intersect_triangle_moller_trumbore(v0, v1, v2, ray, 0.0f, best.t, t, b0, b1, b2);
  if (hit && alpha_keeps<kCode>(scene, b.id[l], ray, t, b1, b2)) keep_if_closer(best, t, b.id[l], b1, b2);
}

// Tests every primitive of the block, keeping the closest (t, id) in `best`. Triangle lanes go
// in order, each against the best hit so far, as the scalar test takes them: a lane the SIMD
// test accepted at the block's tmax is kept where its t is within the best hit's.
template <uint32_t kCode = kTraceAll>
TRACER_HD void test_triangle_block(const SceneView& scene, const TriangleBlock& b, const WideRayQuery& q,
                                   const Ray& ray, const RayShear& shear, Hit& best) {
  for (uint32_t lanes = b.other_lanes; lanes != 0; lanes &= lanes - 1)
    test_primitive<leaf_trace_code<kCode>()>(scene, b.id[lowest_set_bit(lanes)], ray, shear, best);
  if (!traces<kCode>(kFeatureTriangle)) return;
  const bool watertight = tests_watertight<kCode>(scene.settings.triangle_test);
#if defined(TRACER_X86_LANES)
  if (watertight) {
    const BlockHits h = watertight_block_hits(b, q, best.t);
    for (uint32_t lanes = h.hit | h.recompute; lanes != 0; lanes &= lanes - 1) {
      const int l = lowest_set_bit(lanes);
      if ((h.recompute >> l) & 1u) {
        test_triangle_lane<kCode>(scene, b, l, ray, shear, true, best);
      } else if (h.t[l] <= best.t && alpha_keeps<kCode>(scene, b.id[l], ray, h.t[l], h.b1[l], h.b2[l])) {
        keep_if_closer(best, h.t[l], b.id[l], h.b1[l], h.b2[l]);
      }
    }
    return;
  }
#else
  (void)q;
#endif
  for (uint32_t lanes = b.triangle_lanes; lanes != 0; lanes &= lanes - 1)
    test_triangle_lane<kCode>(scene, b, lowest_set_bit(lanes), ray, shear, watertight, best);
}

}  // namespace tracer
