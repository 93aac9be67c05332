// Float-to-integer conversion defined for every input and the same on the host and the GPU:
// truncation toward zero, NaN gives 0, values beyond the type's range give its nearest end.
// That is PTX cvt.rzi's saturating rule (PTX ISA, "cvt"); C++ leaves NaN and out-of-range
// inputs undefined, and x86's cvttss2si gives the "integer indefinite" 0x80000000 for them.
// The range is checked in floating point first, so the conversion itself only ever sees a
// value it converts exactly on both sides. Every float-to-int conversion in kernel code goes
// through this file; the instruction audit (docs/cuda.md) fails on one anywhere else.
#pragma once
#include <cstdint>

#include "kernel/base/platform.h"

namespace tracer {

// x truncated to I, or the end of I's range beyond it: lo and hi are I's range as exact
// powers of two in F (-2^(n-1) and 2^(n-1); 0 and 2^n unsigned), lowest and highest its ends.
template <class I, class F>
TRACER_HD I saturating_trunc(F x, F lo, F hi, I lowest, I highest) {
  if (x != x) return 0;
  if (x >= hi) return highest;
  if (x <= lo) return lowest;  // for unsigned, (-1, 0] too: its truncation is 0
  return static_cast<I>(x);
}

TRACER_HD int32_t trunc_to_int32(float x) {
  return saturating_trunc<int32_t>(x, -0x1p31f, 0x1p31f, INT32_MIN, INT32_MAX);
}
TRACER_HD int32_t trunc_to_int32(double x) {
  return saturating_trunc<int32_t>(x, -0x1p31, 0x1p31, INT32_MIN, INT32_MAX);
}
TRACER_HD int64_t trunc_to_int64(double x) {
  return saturating_trunc<int64_t>(x, -0x1p63, 0x1p63, INT64_MIN, INT64_MAX);
}
TRACER_HD uint32_t trunc_to_uint32(float x) { return saturating_trunc<uint32_t>(x, 0.0f, 0x1p32f, 0u, UINT32_MAX); }

}  // namespace tracer
