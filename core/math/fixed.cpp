// Integer division, wide multiply-divide and square roots (see fixed.h for
// the rounding contract of each).
#include "core/math/fixed.h"

namespace dexmill {
namespace {
bool u128_less(U128 a, U128 b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
}  // namespace

U128 mul_wide_u64_portable(uint64_t a, uint64_t b) {
  uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
  uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
  U128 r;
  r.lo = (mid << 32) | (p00 & 0xffffffffu);
  r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
  return r;
}

U128 sub_u128(U128 a, U128 b) {
  U128 r;
  r.lo = a.lo - b.lo;
  r.hi = a.hi - b.hi - (a.lo < b.lo ? 1u : 0u);
  return r;
}

U128 shl_u128(U128 a, int s) {
  if (s == 0) return a;
  U128 r;
  r.hi = (a.hi << s) | (a.lo >> (64 - s));
  r.lo = a.lo << s;
  return r;
}

uint64_t isqrt_u128(U128 v) {
#if DEXMILL_WIDE_MUL
  // A 64-bit root of the top bits (at least 31 good bits), one Newton step
  // with the compiler's 128-bit division (error below 1 after it), then the
  // exact correction: the same bits as the portable path (tested).
  if (v.hi == 0) return isqrt_fast_u64(v.lo);
  using u128 = unsigned __int128;
  const u128 n = (static_cast<u128>(v.hi) << 64) | v.lo;
  const int bits = 128 - __builtin_clzll(v.hi);
  const int s = (bits - 63) & ~1;  // even; n >> s keeps 63 or 64 bits
  u128 r = static_cast<u128>(isqrt_fast_u64(static_cast<uint64_t>(n >> s))) << (s / 2);
  r = (r + n / r) >> 1;
  if (r > UINT64_MAX) r = UINT64_MAX;
  while (r * r > n) --r;
  while (r < UINT64_MAX && (r + 1) * (r + 1) <= n) ++r;
  return static_cast<uint64_t>(r);
#else
  return isqrt_u128_portable(v);
#endif
}

// Digit-by-digit, two bits of v per step (64 steps): the reference, and the
// path for values whose seeded Newton step cannot run (the quotient of
// v / r0 past 64 bits, near 2^128).
uint64_t isqrt_u128_bitwise(U128 v) {
  // rem fits in 66 bits, tracked as a U128 to stay exact.
  U128 rem{0, 0};
  uint64_t root = 0;
  for (int i = 0; i < 64; ++i) {
    rem = shl_u128(rem, 2);
    rem.lo |= v.hi >> 62;
    v = shl_u128(v, 2);
    U128 trial{root >> 62, (root << 2) | 1u};  // 4*root + 1, then compare
    root <<= 1;
    if (rem.hi > trial.hi || (rem.hi == trial.hi && rem.lo >= trial.lo)) {
      rem = sub_u128(rem, trial);
      root |= 1u;
    }
  }
  return root;
}

// As the 128-bit path does, on 32-bit CPUs (a piece's set-up takes one such
// root; digit by digit it cost about 3 000 instructions on a Cortex-M4): a
// root of the top 63 or 64 bits (31 good bits), one Newton step with the
// 128 / 64-bit division (error below 1 after it), then the exact correction.
uint64_t isqrt_u128_portable(U128 v) {
  if (v.hi == 0) return isqrt_fast_u64(v.lo);
  const int bits = 128 - __builtin_clzll(v.hi);
  const int sh = (bits - 63) & ~1;  // even; v >> sh keeps 63 or 64 bits
  const uint64_t top = sh >= 64 ? v.hi >> (sh - 64) : (v.lo >> sh) | (sh ? v.hi << (64 - sh) : 0);
  const uint64_t r0 = static_cast<uint64_t>(isqrt_fast_u64(top)) << (sh / 2);  // <= sqrt(v), >= 2^32
  if (v.hi >= r0) return isqrt_u128_bitwise(v);
  uint64_t rem;
  const uint64_t q = divmod_u128_portable(v, r0, &rem);
  uint64_t r = (r0 >> 1) + (q >> 1) + (r0 & q & 1u);  // (r0 + q) / 2 without overflow
  while (r != 0 && u128_less(v, mul_wide_u64_portable(r, r))) --r;
  while (r != UINT64_MAX && !u128_less(v, mul_wide_u64_portable(r + 1, r + 1))) ++r;
  return r;
}

// Hacker's Delight's divlu (Warren, figure 9-3): the divisor normalised to
// its top bit, the quotient as two 32-bit digits, each estimated from the
// top two digits over the divisor's top digit and corrected (at most twice).
uint64_t divmod_u128_portable(U128 n, uint64_t d, uint64_t* rem) {
  constexpr uint64_t kB = static_cast<uint64_t>(1) << 32;
  const int s = __builtin_clzll(d);
  d <<= s;
  const uint64_t dn1 = d >> 32, dn0 = d & 0xffffffffu;
  const uint64_t un32 = (n.hi << s) | (s ? n.lo >> (64 - s) : 0);
  const uint64_t un10 = n.lo << s;
  const uint64_t un1 = un10 >> 32, un0 = un10 & 0xffffffffu;
  uint64_t q1 = un32 / dn1, rhat = un32 - q1 * dn1;
  while (q1 >= kB || q1 * dn0 > kB * rhat + un1) {
    --q1;
    rhat += dn1;
    if (rhat >= kB) break;
  }
  const uint64_t un21 = un32 * kB + un1 - q1 * d;  // modulo 2^64: the true value is below d
  uint64_t q0 = un21 / dn1;
  rhat = un21 - q0 * dn1;
  while (q0 >= kB || q0 * dn0 > kB * rhat + un0) {
    --q0;
    rhat += dn1;
    if (rhat >= kB) break;
  }
  *rem = (un21 * kB + un0 - q0 * d) >> s;
  return q1 * kB + q0;
}

namespace {

// (q, rem) of n / d for a 128-bit n and 64-bit d != 0; q saturates at 2^64-1
// (the callers saturate further to int64 anyway).
void divmod_u128(U128 n, uint64_t d, uint64_t* q, uint64_t* rem) {
  if (n.hi >= d) {  // quotient does not fit 64 bits
    *q = UINT64_MAX;
    *rem = 0;
    return;
  }
  *q = divmod_u128_portable(n, d, rem);
}

}  // namespace

// The inline muldiv_round / muldiv_floor (fixed.h) handle products that fit
// 64 bits; this is the rest: the compiler's 128-bit integers where the
// target has them, the portable U128 division elsewhere (the same results).
int64_t muldiv_wide(int64_t a, int64_t b, int64_t c, bool round_nearest) {
#if DEXMILL_WIDE_MUL
  {
    const __int128 p = static_cast<__int128>(a) * b;
    __int128 q = p / c, r = p % c;
    if (round_nearest) {
      const __int128 ar = r < 0 ? -r : r, ac = c < 0 ? -static_cast<__int128>(c) : c;
      if (2 * ar >= ac) q += ((p < 0) != (c < 0)) ? -1 : 1;
    } else if (r != 0 && ((r < 0) != (c < 0))) {
      q -= 1;
    }
    return q > INT64_MAX ? INT64_MAX : (q < INT64_MIN ? INT64_MIN : static_cast<int64_t>(q));
  }
#endif
  bool neg = (a < 0) != (b < 0);
  if (c < 0) neg = !neg;
  uint64_t ua = abs_u64(a), ub = abs_u64(b), uc = abs_u64(c);
  uint64_t q, rem;
  divmod_u128(mul_wide_u64(ua, ub), uc, &q, &rem);
  if (round_nearest) {
    if (rem >= uc - rem && q != UINT64_MAX) ++q;  // ties away from zero
  } else if (neg && rem != 0 && q != UINT64_MAX) {
    ++q;  // floor of a negative quotient moves away from zero
  }
  if (neg) {
    if (q > static_cast<uint64_t>(INT64_MAX) + 1u) return INT64_MIN;
    return q == static_cast<uint64_t>(INT64_MAX) + 1u ? INT64_MIN : -static_cast<int64_t>(q);
  }
  return q > static_cast<uint64_t>(INT64_MAX) ? INT64_MAX : static_cast<int64_t>(q);
}

int64_t mul_shift_portable(int64_t a, int64_t b, int s) {
  const bool neg = (a < 0) != (b < 0) && a != 0 && b != 0;
  U128 m = mul_wide_u64(abs_u64(a), abs_u64(b));
  // Magnitude shifted right, remembering whether bits were dropped (floor of
  // a negative value rounds away from zero).
  uint64_t lo = s ? ((m.lo >> s) | (m.hi << (64 - s))) : m.lo;
  uint64_t hi = s ? (m.hi >> s) : m.hi;
  const bool dropped = s ? (m.lo & ((static_cast<uint64_t>(1) << s) - 1u)) != 0 : false;
  if (neg) {
    if (dropped && ++lo == 0) ++hi;
    if (hi != 0 || lo >= static_cast<uint64_t>(INT64_MAX) + 1u) return INT64_MIN;
    return -static_cast<int64_t>(lo);
  }
  if (hi != 0 || lo > static_cast<uint64_t>(INT64_MAX)) return INT64_MAX;
  return static_cast<int64_t>(lo);
}

uint32_t isqrt_u64(uint64_t v) {
  // Bitwise digit-by-digit root: exact, no division, 32 iterations.
  uint64_t rem = 0, root = 0;
  for (int i = 0; i < 32; ++i) {
    rem = (rem << 2) | (v >> 62);
    v <<= 2;
    root <<= 1;
    uint64_t trial = (root << 1) | 1u;
    if (rem >= trial) {
      rem -= trial;
      root |= 1u;
    }
  }
  return static_cast<uint32_t>(root);
}

uint32_t isqrt_round_u64(uint64_t v) {
  uint64_t r = isqrt_u64(v);
  // sqrt(v) >= r + 0.5  <=>  v >= r^2 + r + 0.25  <=>  v > r^2 + r (integers).
  // r + 1 = 2^32 does not fit: that single case saturates (error < 1).
  if (v > r * r + r) return r == UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(r + 1);
  return static_cast<uint32_t>(r);
}

uint32_t hypot_round(int64_t a, int64_t b) {
  uint64_t ua = abs_u64(a), ub = abs_u64(b);
  return isqrt_round_u64(ua * ua + ub * ub);
}

}  // namespace dexmill
