// Fixed-point and integer arithmetic for the whole of dexmill.
//
// Units (core/README.md "Numbers"): lengths from G-code are int64 nanometres
// (`_nm`), exact for mm with 6 decimals and inch with 5. Grid-space values are
// dexel indices and height LSBs (`_dex`, `_lsb`). Fractions use the Fixed<>
// family below; its name says the number of fraction bits (q16 = 16).
//
// Rounding and overflow are stated per function. Right shift of a negative
// value is arithmetic on every compiler and CPU we support (GCC and clang
// document it); left shift of a negative value is undefined, so code here
// multiplies instead.
#ifndef DEXMILL_CORE_MATH_FIXED_H
#define DEXMILL_CORE_MATH_FIXED_H

#include <stdint.h>
#include <limits>
#include <type_traits>

#include "core/config.h"

namespace dexmill {

constexpr int64_t kNmPerUm = 1000;
constexpr int64_t kNmPerMm = 1000000;
constexpr int64_t kNmPerInch = 25400000;

// ---- clamping and saturating arithmetic ---------------------------------

template <class T>
constexpr T clamp(T v, T lo, T hi) { return v < lo ? lo : (v > hi ? hi : v); }

template <class T>
constexpr T min_of(T a, T b) { return b < a ? b : a; }
template <class T>
constexpr T max_of(T a, T b) { return a < b ? b : a; }

// |v| as unsigned: exact even for the most negative value.
constexpr uint64_t abs_u64(int64_t v) {
  return v < 0 ? static_cast<uint64_t>(0) - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
}

constexpr int32_t sat_i32(int64_t v) {
  return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : static_cast<int32_t>(v));
}

inline int32_t sat_add_i32(int32_t a, int32_t b) {
  int32_t r;
  if (__builtin_add_overflow(a, b, &r)) return b > 0 ? INT32_MAX : INT32_MIN;
  return r;
}
inline int32_t sat_sub_i32(int32_t a, int32_t b) {
  int32_t r;
  if (__builtin_sub_overflow(a, b, &r)) return b < 0 ? INT32_MAX : INT32_MIN;
  return r;
}
inline int32_t sat_mul_i32(int32_t a, int32_t b) {
  int32_t r;
  if (__builtin_mul_overflow(a, b, &r)) return (a < 0) != (b < 0) ? INT32_MIN : INT32_MAX;
  return r;
}
inline int64_t sat_add_i64(int64_t a, int64_t b) {
  int64_t r;
  if (__builtin_add_overflow(a, b, &r)) return b > 0 ? INT64_MAX : INT64_MIN;
  return r;
}
inline int64_t sat_sub_i64(int64_t a, int64_t b) {
  int64_t r;
  if (__builtin_sub_overflow(a, b, &r)) return b < 0 ? INT64_MAX : INT64_MIN;
  return r;
}
inline int64_t sat_mul_i64(int64_t a, int64_t b) {
  int64_t r;
  if (__builtin_mul_overflow(a, b, &r)) return (a < 0) != (b < 0) ? INT64_MIN : INT64_MAX;
  return r;
}

// ---- division with stated rounding (d != 0; INT64_MIN / -1 saturates) --------

// Inline: the sweep's row set-up and stamping call them per row and per
// instance, where a call costs as much as the rest of the work.

// floor(n / d)
inline int64_t div_floor(int64_t n, int64_t d) {
  if (d == -1) return n == INT64_MIN ? INT64_MAX : -n;
  const int64_t q = n / d, r = n % d;
  return (r != 0 && ((r < 0) != (d < 0))) ? q - 1 : q;
}
// ceil(n / d)
inline int64_t div_ceil(int64_t n, int64_t d) {
  if (d == -1) return n == INT64_MIN ? INT64_MAX : -n;
  const int64_t q = n / d, r = n % d;
  return (r != 0 && ((r < 0) == (d < 0))) ? q + 1 : q;
}
// n / d rounded to nearest, ties away from zero.
inline int64_t div_round(int64_t n, int64_t d) {
  if (d == -1) return n == INT64_MIN ? INT64_MAX : -n;
  int64_t q = n / d;
  const int64_t r = n % d;
  // |2r| >= |d| rounds away from zero; compare in unsigned to avoid overflow.
  const uint64_t ar = abs_u64(r), ad = abs_u64(d);
  if (ar >= ad - ar) q += ((n < 0) != (d < 0)) ? -1 : 1;
  return q;
}

// a * b / c with an exact 128-bit intermediate, rounded to nearest (ties
// away from zero) or down (fixed.cpp; portable: no __int128 needed).
int64_t muldiv_wide(int64_t a, int64_t b, int64_t c, bool round_nearest);
// round(a * b / c), ties away from zero, with an exact 128-bit intermediate
// (portable: no __int128, so it runs on 32-bit CPUs). Saturates to the int64
// range. c != 0. Inline when a * b fits 64 bits (one division, as per-piece
// set-up and stamping need); beyond that a 128/64 division, not for inner
// loops.
inline int64_t muldiv_round(int64_t a, int64_t b, int64_t c) {
  int64_t p;
  if (!__builtin_mul_overflow(a, b, &p)) return div_round(p, c);
  return muldiv_wide(a, b, c, true);
}
// floor(a * b / c), same properties.
inline int64_t muldiv_floor(int64_t a, int64_t b, int64_t c) {
  int64_t p;
  if (!__builtin_mul_overflow(a, b, &p)) return div_floor(p, c);
  return muldiv_wide(a, b, c, false);
}

// ---- 128-bit helpers (portable; for set-up code, not inner loops) -----------

struct U128 {
  uint64_t hi, lo;
};
// Exact a * b: the compiler's 128-bit product where the target has one (per
// move set-up uses it), the portable four-product path elsewhere (always
// built, tested equal).
U128 mul_wide_u64_portable(uint64_t a, uint64_t b);
inline U128 mul_wide_u64(uint64_t a, uint64_t b) {
#if DEXMILL_WIDE_MUL
  const unsigned __int128 p = static_cast<unsigned __int128>(a) * b;
  return U128{static_cast<uint64_t>(p >> 64), static_cast<uint64_t>(p)};
#else
  return mul_wide_u64_portable(a, b);
#endif
}
// a - b modulo 2^128 (callers ensure a >= b).
U128 sub_u128(U128 a, U128 b);
// a * 2^s for 0 <= s < 64 (bits shifted out of the top are lost).
U128 shl_u128(U128 a, int s);
// floor(sqrt(v)): exact; the root of a 128-bit value fits 64 bits. Uses the
// compiler's 128-bit integers where the target has them; the portable
// digit-by-digit path (always built, tested equal) elsewhere.
uint64_t isqrt_u128(U128 v);
uint64_t isqrt_u128_portable(U128 v);
uint64_t isqrt_u128_bitwise(U128 v);  // digit by digit: the reference the tests hold both to
// floor(n / d) and n mod d (in *rem) for n.hi < d (the quotient fits 64
// bits), without 128-bit integers: the division of the portable paths
// (always built, tested against the compiler's).
uint64_t divmod_u128_portable(U128 n, uint64_t d, uint64_t* rem);

// floor(a * b / 2^s) for 0 <= s < 64, saturating to the int64 range. Exact:
// uses the compiler's 128-bit integers where the target has them and the
// portable U128 path elsewhere; both give the same bits.
// The portable path of mul_shift, always built (tests compare the two).
// A pure function: `const` lets callers' repeated products share one call.
__attribute__((const)) int64_t mul_shift_portable(int64_t a, int64_t b, int s);
namespace detail {
// 32-bit CPUs: most of the sweep's products (offsets in U, slopes, q30
// factors, the U -> V scale) have both operands within int32, where the
// exact product is one 32 x 32 -> 64 instruction and its floor shift fits
// int64: the same bits as the portable four-product path, which costs about
// ten times as many instructions on a Cortex-M4. (Defined everywhere, so
// that tests compare it with the portable path on any host.)
inline bool fits_i32(int64_t v) { return v == static_cast<int32_t>(v); }
inline int64_t mul_shift_i32(int64_t a, int64_t b, int s) {
  return (static_cast<int64_t>(static_cast<int32_t>(a)) * static_cast<int32_t>(b)) >> s;
}
}  // namespace detail
inline int64_t mul_shift(int64_t a, int64_t b, int s) {
#if DEXMILL_WIDE_MUL
  const __int128 p = static_cast<__int128>(a) * b;
  const __int128 q = p >> s;  // arithmetic shift: floor for negative products
  if (q > INT64_MAX) return INT64_MAX;
  if (q < INT64_MIN) return INT64_MIN;
  return static_cast<int64_t>(q);
#else
  if (detail::fits_i32(a) && detail::fits_i32(b)) return detail::mul_shift_i32(a, b, s);
  return mul_shift_portable(a, b, s);
#endif
}

// mul_shift for inner loops whose caller has proved that floor(a * b / 2^s)
// fits int64 (the product itself may not): the same bits without the
// saturation tests. The portable path is mul_shift's.
// With DEXMILL_CHECKED_ARITH (core/config.h) a result that does not fit
// is reported (UBSan: an unreachable point reached) instead of wrapping.
inline int64_t mul_shift_fit(int64_t a, int64_t b, int s) {
#if DEXMILL_WIDE_MUL
  const __int128 q = (static_cast<__int128>(a) * b) >> s;
  if (kCheckedArith && q != static_cast<int64_t>(q)) __builtin_unreachable();
  return static_cast<int64_t>(q);
#else
  if (detail::fits_i32(a) && detail::fits_i32(b)) return detail::mul_shift_i32(a, b, s);
  const int64_t q = mul_shift_portable(a, b, s);  // saturated: the extremes mean it did not fit
  if (kCheckedArith && (q == INT64_MAX || q == INT64_MIN)) __builtin_unreachable();
  return q;
#endif
}

// ---- integer square roots ---------------------------------------------------

// floor(sqrt(v)): exact for every v (error 0, result <= 2^32 - 1).
uint32_t isqrt_u64(uint64_t v);
// sqrt(v) rounded to nearest: |result - sqrt(v)| <= 0.5 (for v > (2^32-0.5)^2
// the result saturates at 2^32 - 1, error < 1).
uint32_t isqrt_round_u64(uint64_t v);
// floor(sqrt(v)), exact like isqrt_u64, for inner loops: an interpolated
// table seed and one multiply-only Newton step (no division), then an exact
// correction of the last bit or two. Same bits as isqrt_u64 (tested, also
// along the sweep's rows: tests/test_isqrt_rows.cpp).
namespace detail {
constexpr uint64_t isqrt_constexpr(uint64_t v) {  // bisection, v < 2^62
  uint64_t lo = 0, hi = static_cast<uint64_t>(1) << 31;
  while (hi - lo > 1) {
    const uint64_t mid = (lo + hi) / 2;
    if (mid * mid <= v) lo = mid; else hi = mid;
  }
  return lo;
}
// 1/sqrt(m) at the knots m = t / 64 in [1, 4], t = 64..256, as q30:
// floor(sqrt(2^66 / t)), 2^66 / t taken as 16 floor(2^62 / t) plus the
// remainder's share (exact: floor(sqrt(floor(a))) = floor(sqrt(a))).
struct RsqrtKnots {
  uint32_t q30[193];
  constexpr RsqrtKnots() : q30() {
    for (uint64_t t = 64; t <= 256; ++t) {
      const uint64_t n = 16 * ((static_cast<uint64_t>(1) << 62) / t) + 16 * ((static_cast<uint64_t>(1) << 62) % t) / t;
      q30[t - 64] = static_cast<uint32_t>(isqrt_constexpr(n));
    }
  }
};
inline constexpr RsqrtKnots kRsqrtKnots{};
}  // namespace detail

// Why this shape: the sweep takes one root per band column (the ball's half
// chord), and along a row the root moves by about 10^5 U a column (median,
// scale-1k's 3 mm ball on a 0.1 mm grid): carried from the column before,
// a Newton step still misses by about 10^3 U, so each column seeds afresh.
// The seed is 1/sqrt(m) interpolated between knots 1/64 apart: rsqrt is
// convex, so the chord lies above it, by at most h^2/8 max|f''| = 2^-15.4
// relative (the knots are floored: below it by at most a q30 unit). One
// Newton step for sqrt(m) with the seed as its reciprocal, s = g (1 + (1 -
// g y) / 2) with g = m y, leaves 1.5 * 2^-30.8 relative plus the truncations:
// the estimate is within 1 of the root for x < 2^58 and within 3 above
// (measured over every octave). Every product is 32 x 32 -> 64 bits (one
// instruction on a Cortex-M4), and the chain is four products deep where two
// Newton steps on 1/sqrt were seven. The correction loops make the result
// exact whatever the estimate: they stop only at r^2 <= x < (r + 1)^2.
//
// On 32-bit CPUs the same steps in 32-bit words (isqrt_fast_u64_split): the
// normalisation takes x's words apart instead of a 64-bit variable shift,
// and the root is handled in 32 bits (s and the corrections' r fit), so that
// the squares are one 32 x 32 -> 64-bit multiply. Both forms give the same
// bits (tests/test_isqrt_rows checks both on every host). The seed's steps
// are written out in both: shared through one inline function, they cost
// the host's sweep 0.9 % more instructions (paper-w3, callgrind), from the
// register allocation of the loops that inline the root.
namespace detail {
inline uint32_t isqrt_fast_u64_split(uint64_t x) {
  if (x < 4) return x ? 1u : 0u;
  // As below, in 32-bit words: the normalisation (x's top word after an
  // even shift) without a 64-bit variable shift.
  const uint32_t hi = static_cast<uint32_t>(x >> 32), lo = static_cast<uint32_t>(x);
  int lz;
  uint32_t m;  // the top word of x << lz
  if (hi != 0) {
    lz = __builtin_clz(hi) & ~1;  // 0..30
    m = lz ? (hi << lz) | (lo >> (32 - lz)) : hi;
  } else {
    lz = 32 + (__builtin_clz(lo) & ~1);
    m = lo << (lz - 32);
  }
  const int h = lz >> 1;  // 31 - e
  const uint32_t k = (m >> 24) - 64;          // the knot below m, 0..191
  const uint32_t f_q16 = (m >> 8) & 0xffffu;  // m's place between the knots
  const uint32_t ya = kRsqrtKnots.q30[k], yb = kRsqrtKnots.q30[k + 1];
  // ya - yb < 2^23, so the product fits 39 bits; y in [2^29, 2^30].
  const uint32_t y = ya - static_cast<uint32_t>((static_cast<uint64_t>(ya - yb) * f_q16) >> 16);
  const uint32_t g = static_cast<uint32_t>((static_cast<uint64_t>(m) * y) >> 30);  // < 2^31 + 2^16
  // 1 - g y in q30: |d| < 2^17 for a seed within 2^-15.
  const int32_t d = static_cast<int32_t>((static_cast<int64_t>(1) << 30) - static_cast<int64_t>((static_cast<uint64_t>(g) * y) >> 30));
  // s = g + g d / 2, with g halved to fit a signed 32-bit operand: sqrt(m)
  // in q30 with a correction below 2^17 in magnitude, so s is in (2^29,
  // 2^32) and the sum is exact in 32 bits.
  const int32_t corr = static_cast<int32_t>((static_cast<int64_t>(static_cast<int32_t>(g >> 1)) * d) >> 30);
  const uint32_t s = g + static_cast<uint32_t>(corr);
  // sqrt(x) = s 2^(e - 30) = 2 s / 2^h: for h >= 1 that is s >> (h - 1),
  // below 2^32; for h = 0 (x >= 2^62) 2 s, saturated to 2^32 - 1.
  uint32_t r;
  if (h == 0) {
    const uint64_t r2 = static_cast<uint64_t>(s) << 1;
    r = r2 > 0xffffffffu ? 0xffffffffu : static_cast<uint32_t>(r2);
  } else {
    r = s >> (h - 1);
  }
  while (static_cast<uint64_t>(r) * r > x) --r;
  while (r < 0xffffffffu && static_cast<uint64_t>(r + 1) * (r + 1) <= x) ++r;
  return r;
}
}  // namespace detail

inline uint32_t isqrt_fast_u64(uint64_t x) {
#ifndef __SIZEOF_INT128__  // 32-bit CPUs (64-bit words cost two; WebAssembly has them)
  return detail::isqrt_fast_u64_split(x);
#else
  if (x < 4) return x ? 1u : 0u;
  // An even shift puts x's top bit at 62 or 63: sqrt(x) in [2^e, 2^(e+1)),
  // and m = x / 4^e in [1, 4) as q30 (in [2^30, 2^32)), without a branch.
  const int lz = __builtin_clzll(x) & ~1;
  const int e = 31 - (lz >> 1);
  const uint64_t m = (x << lz) >> 32;
  const uint32_t k = static_cast<uint32_t>(m >> 24) - 64;           // the knot below m, 0..191
  const uint32_t f_q16 = static_cast<uint32_t>(m >> 8) & 0xffffu;  // m's place between the knots
  const uint32_t ya = detail::kRsqrtKnots.q30[k], yb = detail::kRsqrtKnots.q30[k + 1];
  // ya - yb < 2^23, so the product fits 39 bits; y in [2^29, 2^30].
  const uint32_t y = ya - static_cast<uint32_t>((static_cast<uint64_t>(ya - yb) * f_q16) >> 16);
  const uint32_t g = static_cast<uint32_t>((static_cast<uint64_t>(static_cast<uint32_t>(m)) * y) >> 30);  // < 2^31 + 2^16
  // 1 - g y in q30: |d| < 2^17 for a seed within 2^-15.
  const int32_t d = static_cast<int32_t>((static_cast<int64_t>(1) << 30) - static_cast<int64_t>((static_cast<uint64_t>(g) * y) >> 30));
  // s = g + g d / 2, with g halved to fit a signed 32-bit operand.
  const int64_t s = static_cast<int64_t>(g) + ((static_cast<int64_t>(static_cast<int32_t>(g >> 1)) * d) >> 30);  // sqrt(m), q30
  // sqrt(x) = s 2^(e - 30); s < 2^32, so s 2 fits and one right shift serves e = 31 too.
  uint64_t r = (static_cast<uint64_t>(s) << 1) >> (31 - e);
  if (r > 0xffffffffu) r = 0xffffffffu;
  while (r * r > x) --r;
  while (r < 0xffffffffu && (r + 1) * (r + 1) <= x) ++r;
  return static_cast<uint32_t>(r);
#endif
}

// sqrt(a^2 + b^2) rounded to nearest for |a|, |b| < 2^31 (error <= 0.5).
uint32_t hypot_round(int64_t a, int64_t b);

// ---- the fixed-point family -------------------------------------------------

// A value `raw / 2^Frac` stored in Rep. Conversions are explicit and say how
// they round; arithmetic that can overflow saturates.
template <class Rep, int Frac>
struct Fixed {
  static_assert(std::is_integral<Rep>::value && std::is_signed<Rep>::value, "signed integer rep");
  static_assert(Frac >= 0 && Frac < static_cast<int>(sizeof(Rep) * 8) - 1, "fraction bits fit the rep");
  using rep_type = Rep;
  static constexpr int kFracBits = Frac;
  static constexpr Rep kOne = static_cast<Rep>(static_cast<Rep>(1) << Frac);

  Rep raw;

  static constexpr Fixed from_raw(Rep r) { return Fixed{r}; }
  // Integer to fixed, saturating at the range of Rep.
  static constexpr Fixed from_int(int64_t i) {
    constexpr int64_t lim = static_cast<int64_t>(std::numeric_limits<Rep>::max()) >> Frac;
    return Fixed{static_cast<Rep>(i > lim ? std::numeric_limits<Rep>::max()
                                          : (i < -lim - 1 ? std::numeric_limits<Rep>::min()
                                                          : static_cast<Rep>(i * kOne)))};
  }
  // num/den as fixed, rounded to nearest (ties away from zero), saturating.
  static Fixed from_ratio(int64_t num, int64_t den) {
    int64_t r = muldiv_round(num, static_cast<int64_t>(kOne), den);
    constexpr int64_t hi = std::numeric_limits<Rep>::max(), lo = std::numeric_limits<Rep>::min();
    return Fixed{static_cast<Rep>(r > hi ? hi : (r < lo ? lo : r))};
  }
  // Largest integer <= value.
  constexpr int64_t floor_int() const { return static_cast<int64_t>(raw) >> Frac; }
  // Nearest integer, ties up (towards +infinity).
  constexpr int64_t round_int() const {
    return (static_cast<int64_t>(raw) + (Frac ? (static_cast<int64_t>(1) << (Frac - 1)) : 0)) >> Frac;
  }
  // Change the number of fraction bits; fewer bits round to nearest (ties
  // up), more bits are exact; saturates to the range of Rep.
  template <int F2>
  constexpr Fixed<Rep, F2> to() const {
    int64_t v = raw;
    if constexpr (F2 < Frac) {
      v = (v + (static_cast<int64_t>(1) << (Frac - F2 - 1))) >> (Frac - F2);
    } else if constexpr (F2 > Frac) {
      constexpr int64_t lim = static_cast<int64_t>(std::numeric_limits<Rep>::max()) >> (F2 - Frac);
      if (v > lim) return Fixed<Rep, F2>{std::numeric_limits<Rep>::max()};
      if (v < -lim - 1) return Fixed<Rep, F2>{std::numeric_limits<Rep>::min()};
      v = v * (static_cast<int64_t>(1) << (F2 - Frac));
    }
    return Fixed<Rep, F2>{static_cast<Rep>(v)};
  }
};

template <class R, int F>
constexpr bool operator==(Fixed<R, F> a, Fixed<R, F> b) { return a.raw == b.raw; }
template <class R, int F>
constexpr bool operator<(Fixed<R, F> a, Fixed<R, F> b) { return a.raw < b.raw; }

// a + b, saturating.
template <int F>
inline Fixed<int32_t, F> sat_add(Fixed<int32_t, F> a, Fixed<int32_t, F> b) {
  return Fixed<int32_t, F>{sat_add_i32(a.raw, b.raw)};
}
// a * b rounded to nearest (ties up), 64-bit intermediate, saturating.
template <int F>
inline Fixed<int32_t, F> sat_mul(Fixed<int32_t, F> a, Fixed<int32_t, F> b) {
  int64_t p = static_cast<int64_t>(a.raw) * b.raw;
  if (F > 0) p = (p + (static_cast<int64_t>(1) << (F - 1 > 0 ? F - 1 : 0))) >> F;
  return Fixed<int32_t, F>{sat_i32(p)};
}

using q16 = Fixed<int32_t, 16>;  // 16.16, e.g. sub-dexel positions
using q30 = Fixed<int32_t, 30>;  // 2.30, unit vectors, sines and cosines

}  // namespace dexmill

#endif
