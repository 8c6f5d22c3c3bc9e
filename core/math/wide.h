// Small exact helpers over core/math/fixed.h's U128 for arc geometry, where the
// squares of lengths up to 2^36 nm (about 68 m) exceed int64.
#ifndef DEXMILL_CORE_MATH_WIDE_H
#define DEXMILL_CORE_MATH_WIDE_H

#include <stdint.h>

#include "core/math/fixed.h"

namespace dexmill {

inline U128 u128_add(U128 a, U128 b) {
  U128 r;
  r.lo = a.lo + b.lo;
  r.hi = a.hi + b.hi + (r.lo < a.lo ? 1u : 0u);
  return r;
}
inline bool u128_less(U128 a, U128 b) { return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo; }
// v^2, exact.
inline U128 sq_u128(int64_t v) { return mul_wide_u64(abs_u64(v), abs_u64(v)); }
// a^2 + b^2, exact (|a|, |b| < 2^63).
inline U128 sum_sq_u128(int64_t a, int64_t b) { return u128_add(sq_u128(a), sq_u128(b)); }
// floor(sqrt(a^2 + b^2)), exact.
inline int64_t hypot_floor(int64_t a, int64_t b) {
  return static_cast<int64_t>(isqrt_u128(sum_sq_u128(a, b)));
}

}  // namespace dexmill

#endif
