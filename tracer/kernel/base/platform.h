// Portability layer for kernel code: the same header compiles as host C++ and as CUDA
// device code. Only correctly rounded IEEE operations live here (docs/determinism.md rule 1).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__CUDACC__)
#define TRACER_HD __host__ __device__ __forceinline__
#define TRACER_HD_STEP TRACER_HD
#else
#define TRACER_HD inline
// An integrator step both schedules call (path_shade, the Whitted steps): inlined into the
// megakernel's loop as the loop body it was, so the path's state stays in registers (GCC left
// it out of line: 0.95x on cornell-box-path).
#define TRACER_HD_STEP inline __attribute__((always_inline))
#endif

namespace tracer {

TRACER_HD uint32_t bits_of(float x) {
#if defined(__CUDA_ARCH__)
  return __float_as_uint(x);
#else
  uint32_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
#endif
}

TRACER_HD float float_of_bits(uint32_t u) {
#if defined(__CUDA_ARCH__)
  return __uint_as_float(u);
#else
  float x;
  std::memcpy(&x, &u, sizeof x);
  return x;
#endif
}

TRACER_HD uint64_t bits_of(double x) {
#if defined(__CUDA_ARCH__)
  return static_cast<uint64_t>(__double_as_longlong(x));
#else
  uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
#endif
}

TRACER_HD double double_of_bits(uint64_t u) {
#if defined(__CUDA_ARCH__)
  return __longlong_as_double(static_cast<long long>(u));
#else
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
#endif
}

// IEEE square root, correctly rounded on the host and under nvcc -prec-sqrt=true.
TRACER_HD float det_sqrt(float x) {
#if defined(__CUDA_ARCH__)
  return __fsqrt_rn(x);
#else
  return std::sqrt(x);
#endif
}

TRACER_HD double det_sqrt(double x) {
#if defined(__CUDA_ARCH__)
  return __dsqrt_rn(x);
#else
  return std::sqrt(x);
#endif
}

TRACER_HD bool is_nan(float x) { return x != x; }
TRACER_HD bool is_nan(double x) { return x != x; }
TRACER_HD bool is_finite(float x) { return (bits_of(x) & 0x7f800000u) != 0x7f800000u; }
TRACER_HD bool is_finite(double x) { return (bits_of(x) & 0x7ff0000000000000ull) != 0x7ff0000000000000ull; }

// min/max with a fixed NaN rule (the second operand wins when a comparison fails), the
// same on every compiler; fminf/fmaxf differ in how they treat NaN and signed zero.
template <class T>
TRACER_HD T min_of(T a, T b) {
  return a < b ? a : b;
}
template <class T>
TRACER_HD T max_of(T a, T b) {
  return a > b ? a : b;
}
#if defined(TRACER_DEVICE_SEMANTICS)
// Kernel code that emulates the GPU on the host (tracer-gpu-device-semantics, docs/cuda.md): float
// min/max follow PTX min.f32/max.f32 (PTX ISA, "Floating Point Instructions: min, max"):
// a NaN operand yields the other one, and -0 orders below +0. Where nvcc emits min/max for
// min_of/max_of, this is what the GPU computes; rendering every golden with it shows that
// no image depends on which of the two forms a site was compiled to.
template <class T>
TRACER_HD T ptx_min(T a, T b) {
  if (a != a) return b;
  if (b != b) return a;
  if (a == b) return bits_of(a) > bits_of(b) ? a : b;  // equal: only +-0 differ, the sign bit set wins
  return a < b ? a : b;
}
template <class T>
TRACER_HD T ptx_max(T a, T b) {
  if (a != a) return b;
  if (b != b) return a;
  if (a == b) return bits_of(a) < bits_of(b) ? a : b;
  return a > b ? a : b;
}
TRACER_HD float min_of(float a, float b) { return ptx_min(a, b); }
TRACER_HD float max_of(float a, float b) { return ptx_max(a, b); }
TRACER_HD double min_of(double a, double b) { return ptx_min(a, b); }
TRACER_HD double max_of(double a, double b) { return ptx_max(a, b); }
#endif
TRACER_HD float abs_of(float x) { return float_of_bits(bits_of(x) & 0x7fffffffu); }
TRACER_HD double abs_of(double x) { return double_of_bits(bits_of(x) & 0x7fffffffffffffffull); }
TRACER_HD float clamp_of(float x, float lo, float hi) { return min_of(max_of(x, lo), hi); }

// Leading zero bits of a 64-bit word; 64 for 0.
TRACER_HD int count_leading_zeros(uint64_t x) {
#if defined(__CUDA_ARCH__)
  return __clzll(static_cast<long long>(x));
#else
  return x == 0 ? 64 : __builtin_clzll(x);
#endif
}

// Adds 1 to a counter shared by threads and returns its old value. The release/acquire
// pair makes what one thread wrote before its increment visible to the thread that sees
// the count it left (a fence on the GPU), as a bottom-up tree pass needs.
TRACER_HD uint32_t atomic_increment(uint32_t* counter) {
#if defined(__CUDA_ARCH__)
  __threadfence();
  const uint32_t old = atomicAdd(counter, 1u);
  __threadfence();
  return old;
#else
  return __atomic_fetch_add(counter, 1u, __ATOMIC_ACQ_REL);
#endif
}

// A float another thread wrote before an atomic_increment this thread has seen: read past
// the GPU's non-coherent L1 cache; on the host the increment's acquire already orders it.
TRACER_HD float load_shared_float(const float* p) {
#if defined(__CUDA_ARCH__)
  return __ldcg(p);
#else
  return *p;
#endif
}

// gamma(n) = n u / (1 - n u), u = 2^-24: the relative error bound of n float operations
// (Higham; pbrt-v4 section 6.8). Intersection tests use it to accept only hits whose t
// is conservatively positive, the second half of self-intersection avoidance.
TRACER_HD constexpr float error_gamma(int n) { return (n * 0x1p-24f) / (1.0f - n * 0x1p-24f); }

constexpr float kPi = 3.14159265358979323846f;
constexpr double kPiD = 3.14159265358979323846;
constexpr float kInfinity = __builtin_huge_valf();

}  // namespace tracer
