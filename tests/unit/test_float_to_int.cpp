// The kernel's float-to-int conversions (kernel/base/float_to_int.h) give PTX cvt.rzi's
// saturating answer for every input, and min_of/max_of follow the rule of the build: the
// ternary's (the second operand wins a failed comparison) or, in the device-semantics
// build, PTX min/max's (NaN yields the other operand, -0 orders below +0).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "kernel/base/float_to_int.h"

using namespace tracer;

namespace {
const float kNanF = std::numeric_limits<float>::quiet_NaN();
const double kNanD = std::numeric_limits<double>::quiet_NaN();
const float kInfF = std::numeric_limits<float>::infinity();
const double kInfD = std::numeric_limits<double>::infinity();
const float kDenormF = std::numeric_limits<float>::denorm_min();
const double kDenormD = std::numeric_limits<double>::denorm_min();
}  // namespace

TEST(FloatToInt, Int32FromFloatSaturatesAndMapsNanToZero) {
  EXPECT_EQ(trunc_to_int32(kNanF), 0);
  EXPECT_EQ(trunc_to_int32(-kNanF), 0);
  EXPECT_EQ(trunc_to_int32(kInfF), INT32_MAX);
  EXPECT_EQ(trunc_to_int32(-kInfF), INT32_MIN);
  EXPECT_EQ(trunc_to_int32(0.0f), 0);
  EXPECT_EQ(trunc_to_int32(-0.0f), 0);
  EXPECT_EQ(trunc_to_int32(kDenormF), 0);
  EXPECT_EQ(trunc_to_int32(-kDenormF), 0);
  EXPECT_EQ(trunc_to_int32(2.99f), 2);
  EXPECT_EQ(trunc_to_int32(-2.99f), -2);
  // The largest float below 2^31 converts exactly; 2^31 and beyond saturate.
  EXPECT_EQ(trunc_to_int32(std::nextafter(0x1p31f, 0.0f)), 2147483520);
  EXPECT_EQ(trunc_to_int32(0x1p31f), INT32_MAX);
  EXPECT_EQ(trunc_to_int32(0x1p40f), INT32_MAX);
  EXPECT_EQ(trunc_to_int32(-0x1p31f), INT32_MIN);
  EXPECT_EQ(trunc_to_int32(std::nextafter(-0x1p31f, -kInfF)), INT32_MIN);
}

TEST(FloatToInt, Int32FromDoubleSaturatesAndMapsNanToZero) {
  EXPECT_EQ(trunc_to_int32(kNanD), 0);
  EXPECT_EQ(trunc_to_int32(kInfD), INT32_MAX);
  EXPECT_EQ(trunc_to_int32(-kInfD), INT32_MIN);
  EXPECT_EQ(trunc_to_int32(-0.0), 0);
  EXPECT_EQ(trunc_to_int32(kDenormD), 0);
  EXPECT_EQ(trunc_to_int32(2147483647.9), INT32_MAX);
  EXPECT_EQ(trunc_to_int32(0x1p31), INT32_MAX);
  EXPECT_EQ(trunc_to_int32(-2147483648.9), INT32_MIN);
  EXPECT_EQ(trunc_to_int32(-2147483647.5), -2147483647);
}

TEST(FloatToInt, Int64FromDoubleSaturatesAndMapsNanToZero) {
  EXPECT_EQ(trunc_to_int64(kNanD), 0);
  EXPECT_EQ(trunc_to_int64(kInfD), INT64_MAX);
  EXPECT_EQ(trunc_to_int64(-kInfD), INT64_MIN);
  EXPECT_EQ(trunc_to_int64(-0.0), 0);
  EXPECT_EQ(trunc_to_int64(-kDenormD), 0);
  EXPECT_EQ(trunc_to_int64(std::nextafter(0x1p63, 0.0)), INT64_C(9223372036854774784));
  EXPECT_EQ(trunc_to_int64(0x1p63), INT64_MAX);
  EXPECT_EQ(trunc_to_int64(-0x1p63), INT64_MIN);
  EXPECT_EQ(trunc_to_int64(std::nextafter(-0x1p63, -kInfD)), INT64_MIN);
  EXPECT_EQ(trunc_to_int64(-4294967296.5), INT64_C(-4294967296));
}

TEST(FloatToInt, Uint32FromFloatSaturatesAtBothEnds) {
  EXPECT_EQ(trunc_to_uint32(kNanF), 0u);
  EXPECT_EQ(trunc_to_uint32(kInfF), UINT32_MAX);
  EXPECT_EQ(trunc_to_uint32(-kInfF), 0u);
  EXPECT_EQ(trunc_to_uint32(-0.0f), 0u);
  EXPECT_EQ(trunc_to_uint32(-0.75f), 0u);  // truncates to -0, which is 0
  EXPECT_EQ(trunc_to_uint32(-5.0f), 0u);   // saturates
  EXPECT_EQ(trunc_to_uint32(kDenormF), 0u);
  EXPECT_EQ(trunc_to_uint32(1023.999f), 1023u);
  EXPECT_EQ(trunc_to_uint32(std::nextafter(0x1p32f, 0.0f)), 4294967040u);
  EXPECT_EQ(trunc_to_uint32(0x1p32f), UINT32_MAX);
}

#if defined(TRACER_DEVICE_SEMANTICS)
TEST(MinMaxRule, FollowsPtxInTheDeviceSemanticsBuild) {
  EXPECT_EQ(min_of(kNanF, 1.0f), 1.0f);
  EXPECT_EQ(min_of(1.0f, kNanF), 1.0f);
  EXPECT_EQ(max_of(kNanF, 1.0f), 1.0f);
  EXPECT_EQ(max_of(1.0f, kNanF), 1.0f);
  EXPECT_TRUE(std::signbit(min_of(0.0f, -0.0f)));
  EXPECT_TRUE(std::signbit(min_of(-0.0f, 0.0f)));
  EXPECT_FALSE(std::signbit(max_of(0.0f, -0.0f)));
  EXPECT_FALSE(std::signbit(max_of(-0.0f, 0.0f)));
  EXPECT_EQ(min_of(kNanD, -2.0), -2.0);
  EXPECT_EQ(max_of(-2.0, kNanD), -2.0);
  EXPECT_EQ(min_of(3u, 2u), 2u);  // integers keep the template
}
#else
TEST(MinMaxRule, TheSecondOperandWinsAFailedComparison) {
  EXPECT_EQ(min_of(kNanF, 1.0f), 1.0f);
  EXPECT_TRUE(std::isnan(min_of(1.0f, kNanF)));
  EXPECT_EQ(max_of(kNanF, 1.0f), 1.0f);
  EXPECT_TRUE(std::isnan(max_of(1.0f, kNanF)));
  EXPECT_TRUE(std::signbit(min_of(0.0f, -0.0f)));
  EXPECT_FALSE(std::signbit(min_of(-0.0f, 0.0f)));
  EXPECT_TRUE(std::signbit(max_of(0.0f, -0.0f)));
  EXPECT_FALSE(std::signbit(max_of(-0.0f, 0.0f)));
}
#endif
