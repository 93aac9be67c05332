// Deterministic transcendental functions (docs/determinism.md rule 2): built only from + - * /,
// sqrt, floor, comparisons and integer operations, so the host and CUDA give the same
// bits. Each float function evaluates in double and rounds once; tests/extremes/test_detmath.cpp
// measures the error against libm's double precision (bound: < 1 ulp, faithful rounding).
#pragma once
#include "kernel/base/float_to_int.h"
#include "kernel/base/platform.h"

namespace tracer {
namespace detmath_detail {

// Word i of 2/pi in binary (fdlibm's ipio2 digits), preceded by one zero word so that
// reduction of arguments below 1 can read "bits before the point" as zeros. A switch,
// not an array, so that the same code is valid in device functions.
TRACER_HD uint32_t two_over_pi_word(int i) {
  switch (i) {
    case 1: return 0xa2f9836eu;
    case 2: return 0x4e441529u;
    case 3: return 0xfc2757d1u;
    case 4: return 0xf534ddc0u;
    case 5: return 0xdb629599u;
    case 6: return 0x3c439041u;
    case 7: return 0xfe5163abu;
    case 8: return 0xdebbc561u;
    default: return 0u;
  }
}
constexpr double kPiOver2 = 0x1.921fb54442d18p+0;
constexpr double kLn2Hi = 0x1.62e42fee00000p-1;  // 32 significant bits: k * kLn2Hi is exact
constexpr double kLn2Lo = 0x1.a39ef35793c76p-33;
constexpr double kInvLn2 = 0x1.71547652b82fep+0;

struct Reduced {
  double r;      // in [-pi/4, pi/4]
  int quadrant;  // x = (4k + quadrant) * pi/2 + r
};

// Payne-Hanek argument reduction for a finite float: x * 2/pi is formed exactly enough
// from a 96-bit window of 2/pi's bits (x = m 2^e with a 24-bit m), so the reduction is
// accurate for every float up to FLT_MAX.
TRACER_HD Reduced reduce_pi_over_2(float x) {
  const uint32_t b = bits_of(x);
  if ((b & 0x7fffffffu) <= 0x3f490fdbu) return {static_cast<double>(x), 0};  // |x| <= pi/4
  const int e = static_cast<int>((b >> 23) & 0xffu) - 150;
  const uint64_t m = (b & 0x7fffffu) | 0x800000u;
  // The bit of 2/pi whose weight in 2^e * (2/pi) is 2^1 sits at table bit e + 30.
  const int first = e + 30;
  const int word = first / 32, shift = first % 32;
  const uint64_t a = (static_cast<uint64_t>(two_over_pi_word(word)) << 32) | two_over_pi_word(word + 1);
  const uint64_t c = (static_cast<uint64_t>(two_over_pi_word(word + 2)) << 32) | two_over_pi_word(word + 3);
  const uint64_t top = shift ? (a << shift) | (c >> (64 - shift)) : a;
  const uint64_t low = c << shift;
  const uint64_t w2 = top >> 32, w1 = top & 0xffffffffu, w0 = low >> 32;
  // P = m * (w2:w1:w0), a 120-bit product; x * 2/pi mod 4 = P * 2^-94.
  const uint64_t p0 = m * w0, p1 = m * w1, p2 = m * w2;
  const uint64_t lo = p0 + (p1 << 32);
  const uint64_t hi = p2 + (p1 >> 32) + (lo < p0 ? 1u : 0u);
  int quadrant = static_cast<int>((hi >> 30) & 3u);
  uint64_t frac = ((hi & 0x3fffffffu) << 34) | (lo >> 30);  // fraction * 2^64
  if (frac >> 63) quadrant = (quadrant + 1) & 3;            // round to the nearest quadrant
  const double f = static_cast<double>(static_cast<int64_t>(frac)) * 0x1p-64;
  double r = f * kPiOver2;
  if (b >> 31) {
    r = -r;
    quadrant = (4 - quadrant) & 3;
  }
  return {r, quadrant};
}

// Taylor series on |r| <= pi/4; the first omitted term is below 2^-53 relative.
TRACER_HD double sin_poly(double r) {
  const double z = r * r;
  double p = -7.647163731819816e-13;
  p = p * z + 1.6059043836821613e-10;
  p = p * z + -2.505210838544172e-08;
  p = p * z + 2.7557319223985893e-06;
  p = p * z + -0.0001984126984126984;
  p = p * z + 0.008333333333333333;
  p = p * z + -0.16666666666666666;
  return r + r * z * p;
}

TRACER_HD double cos_poly(double r) {
  const double z = r * r;
  double p = 4.779477332387385e-14;
  p = p * z + -1.1470745597729725e-11;
  p = p * z + 2.08767569878681e-09;
  p = p * z + -2.755731922398589e-07;
  p = p * z + 2.48015873015873e-05;
  p = p * z + -0.001388888888888889;
  p = p * z + 0.041666666666666664;
  p = p * z + -0.5;
  return 1.0 + z * p;
}

// atan on [0, 1]: two half-angle steps atan(t) = 2 atan(t / (1 + sqrt(1 + t^2))) bring t
// below tan(pi/16), where the alternating series converges to 2^-56 in 12 terms.
TRACER_HD double atan_unit(double t) {
  t = t / (1.0 + det_sqrt(1.0 + t * t));
  t = t / (1.0 + det_sqrt(1.0 + t * t));
  const double z = t * t;
  double p = 1.0 / 25.0;  // coefficient of z^12
  for (int k = 11; k >= 0; --k) p = (k % 2 ? -1.0 : 1.0) / (2 * k + 1) + z * p;
  return 4.0 * t * p;
}

// atan for t >= 0 (t may be +inf).
TRACER_HD double atan_nonneg(double t) { return t > 1.0 ? kPiOver2 - atan_unit(1.0 / t) : atan_unit(t); }

// e^x in double: x = k ln2 + r (Cody-Waite), |r| <= ln2/2, Taylor to r^13.
TRACER_HD double exp_d(double x) {
  if (is_nan(x)) return x;
  if (x > 709.8) return kInfinity;
  if (x < -745.2) return 0.0;
  const double k = static_cast<double>(trunc_to_int64(x * kInvLn2 + (x < 0 ? -0.5 : 0.5)));
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  double p = 1.6059043836821613e-10;
  p = p * r + 2.08767569878681e-09;
  p = p * r + 2.505210838544172e-08;
  p = p * r + 2.755731922398589e-07;
  p = p * r + 2.7557319223985893e-06;
  p = p * r + 2.48015873015873e-05;
  p = p * r + 0.0001984126984126984;
  p = p * r + 0.001388888888888889;
  p = p * r + 0.008333333333333333;
  p = p * r + 0.041666666666666664;
  p = p * r + 0.16666666666666666;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // Scale by 2^k in two exact steps so that neither factor leaves the normal range.
  const int ki = trunc_to_int32(k);
  const int k1 = ki / 2, k2 = ki - k1;
  const double s1 = double_of_bits(static_cast<uint64_t>(1023 + k1) << 52);
  const double s2 = double_of_bits(static_cast<uint64_t>(1023 + k2) << 52);
  return p * s1 * s2;
}

// ln x in double: x = m 2^e with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s),
// s = (m - 1)/(m + 1), |s| < 0.172, series to s^23.
TRACER_HD double log_d(double x) {
  if (is_nan(x) || x < 0.0) return x < 0.0 ? double_of_bits(0x7ff8000000000000ull) : x;
  if (x == 0.0) return -static_cast<double>(kInfinity);
  if (!is_finite(x)) return x;
  int e = 0;
  if (x < 0x1p-1022) {  // subnormal: make it normal first
    x *= 0x1p54;
    e = -54;
  }
  const uint64_t b = bits_of(x);
  e += static_cast<int>((b >> 52) & 0x7ffu) - 1023;
  double m = double_of_bits((b & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
  if (m > 1.4142135623730951) {
    m *= 0.5;
    e += 1;
  }
  const double s = (m - 1.0) / (m + 1.0);
  const double z = s * s;
  double p = 1.0 / 23.0;
  for (int k = 10; k >= 0; --k) p = 1.0 / (2 * k + 1) + z * p;
  const double ed = static_cast<double>(e);
  return ed * kLn2Hi + (ed * kLn2Lo + 2.0 * s * p);
}

TRACER_HD bool is_integer(float y) { return abs_of(y) >= 0x1p23f || static_cast<float>(trunc_to_int32(y)) == y; }
TRACER_HD bool is_odd_integer(float y) { return abs_of(y) < 0x1p24f && is_integer(y) && (trunc_to_int32(y) & 1) != 0; }

}  // namespace detmath_detail

constexpr float kNaN = __builtin_nanf("");

TRACER_HD float det_sin(float x) {
  using namespace detmath_detail;
  if (!is_finite(x)) return kNaN;
  if (abs_of(x) < 0x1p-12f) return x;  // sin x = x - x^3/6 rounds to x
  const Reduced red = reduce_pi_over_2(x);
  switch (red.quadrant) {
    case 0: return static_cast<float>(sin_poly(red.r));
    case 1: return static_cast<float>(cos_poly(red.r));
    case 2: return static_cast<float>(-sin_poly(red.r));
    default: return static_cast<float>(-cos_poly(red.r));
  }
}

TRACER_HD float det_cos(float x) {
  using namespace detmath_detail;
  if (!is_finite(x)) return kNaN;
  const Reduced red = reduce_pi_over_2(x);
  switch (red.quadrant) {
    case 0: return static_cast<float>(cos_poly(red.r));
    case 1: return static_cast<float>(-sin_poly(red.r));
    case 2: return static_cast<float>(-cos_poly(red.r));
    default: return static_cast<float>(sin_poly(red.r));
  }
}

// det_sin(x) and det_cos(x), bit for bit, from one argument reduction.
TRACER_HD void det_sincos(float x, float& s, float& c) {
  using namespace detmath_detail;
  if (!is_finite(x)) {
    s = c = kNaN;
    return;
  }
  const Reduced red = reduce_pi_over_2(x);
  const double sin_r = sin_poly(red.r), cos_r = cos_poly(red.r);
  switch (red.quadrant) {
    case 0: s = static_cast<float>(sin_r), c = static_cast<float>(cos_r); break;
    case 1: s = static_cast<float>(cos_r), c = static_cast<float>(-sin_r); break;
    case 2: s = static_cast<float>(-sin_r), c = static_cast<float>(-cos_r); break;
    default: s = static_cast<float>(-cos_r), c = static_cast<float>(sin_r); break;
  }
  if (abs_of(x) < 0x1p-12f) s = x;  // as det_sin
}

TRACER_HD float det_tan(float x) {
  using namespace detmath_detail;
  if (!is_finite(x)) return kNaN;
  if (abs_of(x) < 0x1p-12f) return x;
  const Reduced red = reduce_pi_over_2(x);
  const double s = sin_poly(red.r), c = cos_poly(red.r);
  return static_cast<float>(red.quadrant % 2 ? -c / s : s / c);
}

// atan2 with C99 Annex F special cases (signed zeros, infinities).
TRACER_HD float det_atan2(float y, float x) {
  using namespace detmath_detail;
  if (is_nan(x) || is_nan(y)) return kNaN;
  const bool y_neg = (bits_of(y) >> 31) != 0, x_neg = (bits_of(x) >> 31) != 0;
  const double ay = abs_of(static_cast<double>(y)), ax = abs_of(static_cast<double>(x));
  double a;
  if (ay == 0.0) {
    a = x_neg ? kPiD : 0.0;
  } else if (ax == 0.0) {
    a = kPiOver2;
  } else if (!is_finite(ay)) {
    a = !is_finite(ax) ? (x_neg ? 3.0 * kPiD / 4.0 : kPiD / 4.0) : kPiOver2;
  } else if (!is_finite(ax)) {
    a = x_neg ? kPiD : 0.0;
  } else {
    a = atan_nonneg(ay / ax);
    if (x_neg) a = kPiD - a;
  }
  return static_cast<float>(y_neg ? -a : a);
}

TRACER_HD float det_asin(float x) {
  using namespace detmath_detail;
  if (is_nan(x) || abs_of(x) > 1.0f) return kNaN;
  if (abs_of(x) < 0x1p-12f) return x;
  const double ax = abs_of(static_cast<double>(x));
  const double a = atan_nonneg(ax / det_sqrt((1.0 - ax) * (1.0 + ax)));
  return static_cast<float>(x < 0 ? -a : a);
}

TRACER_HD float det_acos(float x) {
  using namespace detmath_detail;
  if (is_nan(x) || abs_of(x) > 1.0f) return kNaN;
  const double xd = x;
  const double s = det_sqrt((1.0 - xd) * (1.0 + xd));
  if (xd == 0.0) return static_cast<float>(kPiOver2);
  const double a = atan_nonneg(s / abs_of(xd));
  return static_cast<float>(xd < 0 ? kPiD - a : a);
}

TRACER_HD float det_exp(float x) {
  using namespace detmath_detail;
  if (is_nan(x)) return x;
  if (x > 100.0f) return kInfinity;
  if (x < -110.0f) return 0.0f;
  return static_cast<float>(exp_d(x));
}

// A NaN is answered before the widening: cvt.f64.f32 turns a signaling NaN quiet on the GPU,
// while GCC may fold the float -> double -> float round trip away (test math.unoptimized).
TRACER_HD float det_log(float x) {
  if (is_nan(x)) return x;
  return static_cast<float>(detmath_detail::log_d(x));
}

// pow with the special cases of C99 Annex F.9.4.4.
TRACER_HD float det_pow(float x, float y) {
  using namespace detmath_detail;
  if (y == 0.0f || x == 1.0f) return 1.0f;
  if (is_nan(x) || is_nan(y)) return kNaN;
  const float ax = abs_of(x);
  if (!is_finite(y)) {
    if (ax == 1.0f) return 1.0f;
    return ((ax < 1.0f) == (y < 0.0f)) ? kInfinity : 0.0f;
  }
  const bool odd = is_odd_integer(y);
  const bool x_neg = (bits_of(x) >> 31) != 0;
  if (x_neg && is_finite(x) && x != 0.0f && !is_integer(y)) return kNaN;
  const float sign = (x_neg && odd) ? -1.0f : 1.0f;
  if (ax == 0.0f) return sign * (y < 0.0f ? kInfinity : 0.0f);
  if (!is_finite(ax)) return sign * (y < 0.0f ? 0.0f : kInfinity);
  const double z = static_cast<double>(y) * log_d(ax);
  return sign * static_cast<float>(exp_d(z));
}

}  // namespace tracer
