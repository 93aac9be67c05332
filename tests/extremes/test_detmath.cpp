// The deterministic math functions against libm's double precision. Stated bound: every
// result is within 0.501 ulp of the exact value (each function evaluates in double and
// rounds once, so it is correctly rounded but for rare double-rounding cases).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "kernel/base/detmath.h"

using namespace tracer;

namespace {

constexpr double kUlpBound = 0.501;

// Error of a float result in units of the last place of the exact (double) value.
double ulp_error(float got, double exact) {
  if (std::isnan(exact)) return std::isnan(got) ? 0.0 : INFINITY;
  if (std::isinf(static_cast<float>(exact)) && std::fabs(exact) > 3.4028235677973366e38)
    return got == static_cast<float>(exact) ? 0.0 : INFINITY;
  int e;
  std::frexp(exact, &e);
  const double ulp = std::ldexp(1.0, std::max(e - 24, -149));
  return std::fabs(static_cast<double>(got) - exact) / ulp;
}

struct Sweep {
  double max_error = 0.0;
  float worst = 0.0f;
  void add(float x, float got, double exact) {
    const double err = ulp_error(got, exact);
    if (err > max_error) max_error = err, worst = x;
  }
};

// Dense sweep: uniform values in [lo, hi] plus log-spaced magnitudes in [lo_mag, hi_mag].
template <class F, class R>
Sweep sweep1(F f, R ref, float lo, float hi, float lo_mag, float hi_mag, bool negative_too) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> lin(lo, hi);
  std::uniform_real_distribution<double> lg(std::log2(lo_mag), std::log2(hi_mag));
  Sweep s;
  for (int i = 0; i < 1000000; ++i) {
    float x = lin(rng);
    s.add(x, f(x), ref(static_cast<double>(x)));
    x = static_cast<float>(std::exp2(lg(rng)));
    if (negative_too && (i & 1)) x = -x;
    s.add(x, f(x), ref(static_cast<double>(x)));
  }
  return s;
}

#define EXPECT_SWEEP_WITHIN_BOUND(sweep)                                 \
  do {                                                                   \
    const Sweep s_ = (sweep);                                            \
    EXPECT_LE(s_.max_error, kUlpBound) << "worst argument " << s_.worst; \
    RecordProperty("max_ulp_error", std::to_string(s_.max_error));       \
  } while (0)

}  // namespace

TEST(DetMath, SinSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(sweep1([](float x) { return det_sin(x); }, [](double x) { return std::sin(x); }, -10.0f,
                                   10.0f, 1e-8f, 1e6f, true));
}
TEST(DetMath, CosSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(sweep1([](float x) { return det_cos(x); }, [](double x) { return std::cos(x); }, -10.0f,
                                   10.0f, 1e-8f, 1e6f, true));
}
TEST(DetMath, TanSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(
      sweep1([](float x) { return det_tan(x); }, [](double x) { return std::tan(x); }, -1.6f, 1.6f, 1e-8f, 1e5f, true));
}
TEST(DetMath, AsinSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(sweep1([](float x) { return det_asin(x); }, [](double x) { return std::asin(x); }, -1.0f,
                                   1.0f, 1e-10f, 1.0f, true));
}
TEST(DetMath, AcosSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(sweep1([](float x) { return det_acos(x); }, [](double x) { return std::acos(x); }, -1.0f,
                                   1.0f, 1e-10f, 1.0f, true));
}
TEST(DetMath, ExpSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(sweep1([](float x) { return det_exp(x); }, [](double x) { return std::exp(x); }, -103.0f,
                                   88.7f, 1e-10f, 100.0f, true));
}
TEST(DetMath, LogSweep) {
  EXPECT_SWEEP_WITHIN_BOUND(sweep1([](float x) { return det_log(x); }, [](double x) { return std::log(x); }, 0.0f, 4.0f,
                                   1e-44f, 3e38f, false));
}
TEST(DetMath, Atan2Sweep) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> d(-10.0f, 10.0f);
  std::uniform_real_distribution<double> lg(-30.0, 30.0);
  Sweep s;
  for (int i = 0; i < 1000000; ++i) {
    float y = d(rng), x = d(rng);
    if (i & 1)
      y = static_cast<float>(std::exp2(lg(rng))) * (y < 0 ? -1 : 1),
      x = static_cast<float>(std::exp2(lg(rng))) * (x < 0 ? -1 : 1);
    s.add(x, det_atan2(y, x), std::atan2(static_cast<double>(y), static_cast<double>(x)));
  }
  EXPECT_SWEEP_WITHIN_BOUND(s);
}
TEST(DetMath, PowSweep) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> lx(-20.0, 20.0);
  std::uniform_real_distribution<float> dy(-6.0f, 6.0f);
  Sweep s;
  for (int i = 0; i < 1000000; ++i) {
    const float x = static_cast<float>(std::exp2(lx(rng)));
    const float y = (i % 4 == 0) ? std::round(dy(rng)) : dy(rng);
    s.add(x, det_pow(x, y), std::pow(static_cast<double>(x), static_cast<double>(y)));
    s.add(-x, det_pow(-x, std::round(y)), std::pow(-static_cast<double>(x), std::round(static_cast<double>(y))));
  }
  EXPECT_SWEEP_WITHIN_BOUND(s);
}

// Huge arguments: every float exponent up to FLT_MAX, against libm's exact reduction.
TEST(DetMath, SinCosHugeArguments) {
  std::mt19937 rng(3);
  Sweep s;
  for (int i = 0; i < 1000000; ++i) {
    const uint32_t bits = rng() & 0x7f7fffffu;  // finite, any exponent below 255
    const float x = float_of_bits(bits | (i & 1 ? 0x80000000u : 0u));
    s.add(x, det_sin(x), std::sin(static_cast<double>(x)));
    s.add(x, det_cos(x), std::cos(static_cast<double>(x)));
  }
  EXPECT_SWEEP_WITHIN_BOUND(s);
  EXPECT_LE(ulp_error(det_sin(3.4028235e38f), std::sin(static_cast<double>(3.4028235e38f))), kUlpBound);
  EXPECT_LE(ulp_error(det_cos(3.4028235e38f), std::cos(static_cast<double>(3.4028235e38f))), kUlpBound);
}

// det_sincos shares one argument reduction and must equal det_sin and det_cos bit for bit:
// every float in [-8, 8] at a stride, huge and tiny arguments, infinities and NaN.
TEST(DetMath, SinCosPairEqualsSinAndCos) {
  std::mt19937 rng(5);
  std::vector<float> xs = {0.0f,   -0.0f,     0x1p-12f,   -0x1p-12f, 0x1.fffffep-13f, 3.4028235e38f, -3.4028235e38f,
                           1e-45f, kInfinity, -kInfinity, kNaN};
  for (uint32_t bits = 0; bits < 0x41000000u; bits += 997)
    xs.insert(xs.end(), {float_of_bits(bits), -float_of_bits(bits)});
  for (int i = 0; i < 200000; ++i) xs.push_back(float_of_bits(rng() & 0xff7fffffu));
  for (float x : xs) {
    float s, c;
    det_sincos(x, s, c);
    ASSERT_EQ(bits_of(s), bits_of(det_sin(x))) << x;
    ASSERT_EQ(bits_of(c), bits_of(det_cos(x))) << x;
  }
}

// Every special value, compared bit for bit with what glibc's float functions return
// (whose special cases follow C99 Annex F).
TEST(DetMath, EdgeValuesMatchAnnexF) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float tiny = std::numeric_limits<float>::denorm_min(), huge = std::numeric_limits<float>::max();
  const float xs[] = {0.0f,  -0.0f, tiny,  -tiny, 1e-30f, -1e-30f, 1.0f, -1.0f, 0.5f, -0.5f, 2.0f,
                      -2.0f, 3.0f,  -3.0f, 0.7f,  huge,   -huge,   inf,  -inf,  nan,  1e30f, -1e30f};
  auto same = [](float a, float b) { return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, 4) == 0; };
  for (float x : xs) {
    if (std::isfinite(x)) {
      EXPECT_LE(ulp_error(det_sin(x), std::sin(static_cast<double>(x))), kUlpBound) << x;
      EXPECT_LE(ulp_error(det_cos(x), std::cos(static_cast<double>(x))), kUlpBound) << x;
      EXPECT_LE(ulp_error(det_tan(x), std::tan(static_cast<double>(x))), kUlpBound) << x;
    } else {
      EXPECT_TRUE(std::isnan(det_sin(x)) && std::isnan(det_cos(x)) && std::isnan(det_tan(x))) << x;
    }
    EXPECT_TRUE(same(det_asin(x), std::asin(x)) ||
                ulp_error(det_asin(x), std::asin(static_cast<double>(x))) <= kUlpBound)
        << x;
    EXPECT_TRUE(same(det_acos(x), std::acos(x)) ||
                ulp_error(det_acos(x), std::acos(static_cast<double>(x))) <= kUlpBound)
        << x;
    EXPECT_TRUE(same(det_exp(x), std::exp(x)) || ulp_error(det_exp(x), std::exp(static_cast<double>(x))) <= kUlpBound)
        << x;
    EXPECT_TRUE(same(det_log(x), std::log(x)) || ulp_error(det_log(x), std::log(static_cast<double>(x))) <= kUlpBound)
        << x;
    for (float y : xs) {
      const float ref_atan2 = std::atan2(y, x), ref_pow = std::pow(x, y);
      EXPECT_TRUE(same(det_atan2(y, x), ref_atan2) ||
                  ulp_error(det_atan2(y, x), std::atan2(static_cast<double>(y), static_cast<double>(x))) <= kUlpBound)
          << "atan2(" << y << ", " << x << ")";
      EXPECT_TRUE(same(det_pow(x, y), ref_pow) ||
                  ulp_error(det_pow(x, y), std::pow(static_cast<double>(x), static_cast<double>(y))) <= kUlpBound)
          << "pow(" << x << ", " << y << ") = " << det_pow(x, y) << ", libm " << ref_pow;
    }
  }
  // Signed zeros are kept exactly.
  EXPECT_TRUE(same(det_sin(-0.0f), -0.0f));
  EXPECT_TRUE(same(det_tan(-0.0f), -0.0f));
  EXPECT_TRUE(same(det_asin(-0.0f), -0.0f));
  EXPECT_TRUE(same(det_atan2(-0.0f, 1.0f), -0.0f));
  EXPECT_EQ(det_cos(0.0f), 1.0f);
  EXPECT_EQ(det_exp(0.0f), 1.0f);
  EXPECT_EQ(det_log(1.0f), 0.0f);
  EXPECT_EQ(det_pow(0.0f, 0.0f), 1.0f);
  EXPECT_EQ(det_pow(inf, 0.0f), 1.0f);
  EXPECT_EQ(det_pow(0.0f, -1.0f), inf);
  EXPECT_TRUE(same(det_pow(-0.0f, -1.0f), -inf));
  EXPECT_EQ(det_pow(2.0f, inf), inf);
  EXPECT_EQ(det_pow(0.5f, inf), 0.0f);
}
