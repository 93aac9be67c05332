// The slab test of kernel/accel/bvh_node.h for the 8 child boxes of a WideBvhNode at once.
// Each lane performs the scalar test's operations in the scalar test's order:
// t0 = (near - o) * inv, t1 = (far - o) * inv * kSlabWiden, tmin = t0 > tmin ? t0 : tmin,
// tmax = t1 < tmax ? t1 : tmax per axis, hit when tmin <= tmax. MAXPS(a, b) and MINPS(a, b)
// return b unless a > b (a < b), NaN included, so the SSE and AVX lanes are those
// comparisons exactly and every lane agrees with the scalar test bit for bit.
#pragma once
#if !defined(__CUDA_ARCH__) && (defined(__x86_64__) || defined(_M_X64))
#include <immintrin.h>
#define TRACER_X86_LANES 1
#endif

#include <cstddef>

#include "kernel/accel/bvh_node.h"
#include "kernel/accel/wide_bvh_node.h"
#include "kernel/geom/triangle.h"

namespace tracer {

// What the box tests and the triangle blocks need of a ray, computed once per ray.
struct WideRayQuery {
  float origin[3];
  float inv_dir[3];
  // Where axis a's near and far planes start in a WideBvhNode, in floats: hi[a] is the near
  // plane where the direction's sign bit is set, lo[a] otherwise. Chosen once per ray, not
  // once per node.
  uint32_t near_plane[3], far_plane[3];
  int k[3];  // the watertight test's axes kx, ky, kz (kernel/geom/triangle.h)
  float sx, sy, sz;
};

TRACER_HD WideRayQuery make_wide_ray_query(const Ray& ray, const RayShear& shear) {
  WideRayQuery q;
  const Vec3 inv = inverse_direction(ray.dir);
  for (int a = 0; a < 3; ++a) {
    q.origin[a] = ray.origin[a];
    q.inv_dir[a] = inv[a];
    const uint32_t near_is_hi = bits_of(ray.dir[a]) >> 31;
    const uint32_t lo = static_cast<uint32_t>(a * kWideBvhWidth), hi = lo + 3u * kWideBvhWidth;
    q.near_plane[a] = near_is_hi ? hi : lo;
    q.far_plane[a] = near_is_hi ? lo : hi;
  }
  q.k[0] = shear.kx, q.k[1] = shear.ky, q.k[2] = shear.kz;
  q.sx = shear.sx, q.sy = shear.sy, q.sz = shear.sz;
  return q;
}

// Bit i set when child i's box meets the ray within [0, tmax]; t_enter[i] is where it enters.
TRACER_HD uint32_t wide_box_hits(const WideBvhNode& n, const WideRayQuery& q, float tmax, float* t_enter) {
  static_assert(offsetof(WideBvhNode, lo) == 0 && offsetof(WideBvhNode, hi) == sizeof n.lo, "planes first");
  const float* planes = reinterpret_cast<const float*>(&n);
  const float* near_plane[3] = {planes + q.near_plane[0], planes + q.near_plane[1], planes + q.near_plane[2]};
  const float* far_plane[3] = {planes + q.far_plane[0], planes + q.far_plane[1], planes + q.far_plane[2]};
#if defined(TRACER_X86_LANES) && defined(__AVX__)
  __m256 lo_t = _mm256_setzero_ps(), hi_t = _mm256_set1_ps(tmax);
  const __m256 widen = _mm256_set1_ps(kSlabWiden);
  for (int a = 0; a < 3; ++a) {
    const __m256 o = _mm256_set1_ps(q.origin[a]), inv = _mm256_set1_ps(q.inv_dir[a]);
    const __m256 t0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(near_plane[a]), o), inv);
    const __m256 t1 = _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(far_plane[a]), o), inv), widen);
    lo_t = _mm256_max_ps(t0, lo_t);
    hi_t = _mm256_min_ps(t1, hi_t);
  }
  _mm256_storeu_ps(t_enter, lo_t);
  return static_cast<uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(lo_t, hi_t, _CMP_LE_OQ)));
#elif defined(TRACER_X86_LANES)
  uint32_t hits = 0;
  const __m128 widen = _mm_set1_ps(kSlabWiden);
  for (int half = 0; half < kWideBvhWidth; half += 4) {
    __m128 lo_t = _mm_setzero_ps(), hi_t = _mm_set1_ps(tmax);
    for (int a = 0; a < 3; ++a) {
      const __m128 o = _mm_set1_ps(q.origin[a]), inv = _mm_set1_ps(q.inv_dir[a]);
      const __m128 t0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(near_plane[a] + half), o), inv);
      const __m128 t1 = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(_mm_load_ps(far_plane[a] + half), o), inv), widen);
      lo_t = _mm_max_ps(t0, lo_t);
      hi_t = _mm_min_ps(t1, hi_t);
    }
    _mm_storeu_ps(t_enter + half, lo_t);
    hits |= static_cast<uint32_t>(_mm_movemask_ps(_mm_cmple_ps(lo_t, hi_t))) << half;
  }
  return hits;
#else
  uint32_t hits = 0;
  for (int i = 0; i < kWideBvhWidth; ++i) {
    float lo_t = 0.0f, hi_t = tmax;
    for (int a = 0; a < 3; ++a) {
      const float t0 = (near_plane[a][i] - q.origin[a]) * q.inv_dir[a];
      const float t1 = (far_plane[a][i] - q.origin[a]) * q.inv_dir[a] * kSlabWiden;
      lo_t = max_of(t0, lo_t);  // t0 > lo_t ? t0 : lo_t, the scalar test's (bvh_node.h)
      hi_t = min_of(t1, hi_t);
    }
    t_enter[i] = lo_t;
    if (lo_t <= hi_t) hits |= 1u << i;
  }
  return hits;
#endif
}

}  // namespace tracer
