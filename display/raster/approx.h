// The two approximations the display needs in integer arithmetic: a
// reciprocal (perspective division) and a reciprocal square root (normal
// normalisation). Both normalise their argument with a count of leading
// zeros, start from a 256-entry table and refine with Newton steps, so they
// cost a few multiplies and no division: what an FPU-less MCU wants.
//
// Error bounds (tests/test_display_approx.cpp checks them against a double
// oracle over all table intervals and millions of random arguments):
//   recip_u32:  |m * 2^-shift - 1/v| <= 2^-28 / v            (relative 3.8e-9)
//   rsqrt_u32:  |m * 2^-shift - 1/sqrt(v)| <= 2^-28 / sqrt(v) (relative 3.8e-9)
//   rsqrt_fast_u32 (one Newton step, for 8-bit shading):
//               |m * 2^-shift - 1/sqrt(v)| <= 2^-15 / sqrt(v) (relative 3.1e-5)
//   normal_unit_q14: each component within 2 q14 LSB (1.2e-4) of the exact
//               unit vector, for any non-zero integer vector.
#ifndef DEXMILL_DISPLAY_RASTER_APPROX_H
#define DEXMILL_DISPLAY_RASTER_APPROX_H

#include <stdint.h>

namespace dexmill {

// 1/v or 1/sqrt(v) as m * 2^-shift, m in [2^30, 2^31].
struct ScaledRecip {
  uint32_t m;
  int32_t shift;
};

// 1/v for v >= 1 (v = 0 is treated as 1).
ScaledRecip recip_u32(uint32_t v);
// 1/sqrt(v) for v >= 1 (v = 0 is treated as 1).
ScaledRecip rsqrt_u32(uint32_t v);
ScaledRecip rsqrt_fast_u32(uint32_t v);

// round(x * m * 2^-shift) for |x| < 2^32 and shift in [1, 63].
inline int64_t scale_recip(int64_t x, ScaledRecip r) {
  const bool neg = x < 0;
  const uint64_t ax = neg ? 0u - static_cast<uint64_t>(x) : static_cast<uint64_t>(x);
  const uint64_t p = ax * r.m;  // < 2^63
  const uint64_t q = (p + (static_cast<uint64_t>(1) << (r.shift - 1))) >> r.shift;
  return neg ? -static_cast<int64_t>(q) : static_cast<int64_t>(q);
}

// A unit vector in q14 (16384 = 1).
struct UnitQ14 {
  int32_t x, y, z;
};

// The direction of (x, y, z) as a q14 unit vector; (0, 0, 16384) for the
// zero vector. Any int64 components.
UnitQ14 normal_unit_q14(int64_t x, int64_t y, int64_t z);

}  // namespace dexmill

#endif
