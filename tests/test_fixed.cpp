// core/math/fixed.h: saturation, rounding divisions, wide muldiv, square roots,
// against exact or double-precision oracles.
#include <cmath>
#include <cstdint>
#include <random>

#include "core/math/fixed.h"
#include "tests/runner.h"

using namespace dexmill;

TEST(fixed_saturating_i32) {
  CHECK_EQ(sat_add_i32(INT32_MAX, 1), INT32_MAX);
  CHECK_EQ(sat_add_i32(INT32_MIN, -1), INT32_MIN);
  CHECK_EQ(sat_add_i32(5, -7), -2);
  CHECK_EQ(sat_sub_i32(INT32_MIN, 1), INT32_MIN);
  CHECK_EQ(sat_sub_i32(INT32_MAX, -1), INT32_MAX);
  CHECK_EQ(sat_mul_i32(65536, 65536), INT32_MAX);
  CHECK_EQ(sat_mul_i32(-65536, 65536), INT32_MIN);
  CHECK_EQ(sat_mul_i32(-3, 7), -21);
  CHECK_EQ(sat_i32(int64_t(1) << 40), INT32_MAX);
  CHECK_EQ(sat_i32(-(int64_t(1) << 40)), INT32_MIN);
}

TEST(fixed_saturating_i64) {
  CHECK_EQ(sat_add_i64(INT64_MAX, 1), INT64_MAX);
  CHECK_EQ(sat_add_i64(INT64_MIN, -1), INT64_MIN);
  CHECK_EQ(sat_sub_i64(INT64_MIN, 1), INT64_MIN);
  CHECK_EQ(sat_mul_i64(int64_t(1) << 32, int64_t(1) << 32), INT64_MAX);
  CHECK_EQ(sat_mul_i64(-(int64_t(1) << 32), int64_t(1) << 32), INT64_MIN);
  CHECK_EQ(abs_u64(INT64_MIN), uint64_t(1) << 63);
}

TEST(fixed_division_rounding) {
  // Exhaustive over a small window against the long-double oracle.
  for (int64_t n = -50; n <= 50; ++n) {
    for (int64_t d = -7; d <= 7; ++d) {
      if (d == 0) continue;
      long double q = static_cast<long double>(n) / d;
      CHECK_EQ(div_floor(n, d), static_cast<int64_t>(std::floor(q)));
      CHECK_EQ(div_ceil(n, d), static_cast<int64_t>(std::ceil(q)));
      // Ties away from zero.
      long double r = q < 0 ? -std::floor(-q + 0.5L) : std::floor(q + 0.5L);
      CHECK_EQ(div_round(n, d), static_cast<int64_t>(r));
    }
  }
  CHECK_EQ(div_round(INT64_MIN, -1), INT64_MAX);
  CHECK_EQ(div_floor(INT64_MIN, -1), INT64_MAX);
  CHECK_EQ(div_round(INT64_MAX, 2), int64_t(1) << 62);
}

TEST(fixed_muldiv_wide) {
#ifdef __SIZEOF_INT128__
  std::mt19937_64 rng(12345);
  for (int it = 0; it < 20000; ++it) {
    int64_t a = static_cast<int64_t>(rng()) >> (rng() % 40);
    int64_t b = static_cast<int64_t>(rng()) >> (rng() % 40);
    int64_t c = static_cast<int64_t>(rng()) >> (rng() % 62);
    if (c == 0) c = 3;
    __int128 p = static_cast<__int128>(a) * b;
    __int128 q = p / c, r = p % c;
    __int128 fl = (r != 0 && ((r < 0) != (c < 0))) ? q - 1 : q;
    __int128 ar = r < 0 ? -r : r, ac = c < 0 ? -static_cast<__int128>(c) : c;
    __int128 ro = q + ((2 * ar >= ac) ? (((p < 0) != (c < 0)) ? -1 : 1) : 0);
    auto sat = [](__int128 v) {
      return v > INT64_MAX ? INT64_MAX : (v < INT64_MIN ? INT64_MIN : static_cast<int64_t>(v));
    };
    if (!CHECK_EQ(muldiv_floor(a, b, c), sat(fl))) break;
    if (!CHECK_EQ(muldiv_round(a, b, c), sat(ro))) break;
  }
#endif
  CHECK_EQ(muldiv_round(INT64_MAX, INT64_MAX, 1), INT64_MAX);
  CHECK_EQ(muldiv_round(INT64_MIN, INT64_MAX, 1), INT64_MIN);
  CHECK_EQ(muldiv_round(INT64_MAX, INT64_MAX, INT64_MAX), INT64_MAX);
  CHECK_EQ(muldiv_floor(-1, 1, 3), -1);
  CHECK_EQ(muldiv_round(-3, 1, 2), -2);
}

TEST(fixed_isqrt_exact) {
  std::mt19937_64 rng(7);
  for (int it = 0; it < 50000; ++it) {
    uint64_t v = rng() >> (rng() % 64);
    uint64_t r = isqrt_u64(v);
    // r^2 <= v < (r+1)^2, checked without overflow.
    if (!CHECK_LE(r * r, v)) break;
    if (r < 0xffffffffu) CHECK_GT((r + 1) * (r + 1), v);
  }
  CHECK_EQ(isqrt_u64(0), 0u);
  CHECK_EQ(isqrt_u64(UINT64_MAX), 0xffffffffu);
  CHECK_EQ(isqrt_u64((uint64_t(1) << 62)), uint32_t(1) << 31);
}

TEST(fixed_isqrt_round_bound) {
  // Stated bound: |result - sqrt(v)| <= 0.5, against the long-double oracle.
  std::mt19937_64 rng(8);
  for (int it = 0; it < 50000; ++it) {
    uint64_t v = rng() >> (rng() % 63 + 1);
    long double s = std::sqrt(static_cast<long double>(v));
    if (!CHECK_NEAR(static_cast<long double>(isqrt_round_u64(v)), s, 0.5L)) break;
  }
  CHECK_EQ(hypot_round(3, 4), 5u);
  CHECK_EQ(hypot_round(-3, -4), 5u);
}

TEST(fixed_isqrt_u128) {
  std::mt19937_64 rng(9);
  for (int it = 0; it < 3000; ++it) {
    U128 v{it % 5 == 0 ? 0 : rng() >> (rng() % 64), rng()};
    uint64_t r = isqrt_u128(v);
    if (!CHECK_EQ(r, isqrt_u128_portable(v))) break;
    U128 sq = mul_wide_u64(r, r);
    bool le = sq.hi < v.hi || (sq.hi == v.hi && sq.lo <= v.lo);
    if (!CHECK(le)) break;
    if (r != UINT64_MAX) {
      U128 s1 = mul_wide_u64(r + 1, r + 1);
      bool gt = s1.hi > v.hi || (s1.hi == v.hi && s1.lo > v.lo);
      if (!CHECK(gt)) break;
    }
  }
  CHECK_EQ(isqrt_u128(U128{0, 0}), 0u);
  CHECK_EQ(isqrt_u128(U128{UINT64_MAX, UINT64_MAX}), UINT64_MAX);
  CHECK_EQ(isqrt_u128_portable(U128{UINT64_MAX, UINT64_MAX}), UINT64_MAX);
  // Perfect squares and their neighbours around 2^64 and at the top.
  for (uint64_t r : {uint64_t{1} << 32, (uint64_t{1} << 32) + 1, uint64_t{0xfffffffffffffffe}, uint64_t{3037000499}}) {
    const U128 sq = mul_wide_u64(r, r);
    CHECK_EQ(isqrt_u128(sq), r);
    CHECK_EQ(isqrt_u128(sub_u128(sq, U128{0, 1})), r - 1);
  }
}

TEST(fixed_family_conversions) {
  q16 a = q16::from_int(3);
  CHECK_EQ(a.raw, 3 << 16);
  CHECK_EQ(q16::from_int(40000).raw, INT32_MAX);  // saturates
  CHECK_EQ(q16::from_int(-40000).raw, INT32_MIN);
  q16 third = q16::from_ratio(1, 3);
  CHECK_EQ(third.raw, 21845);
  CHECK_EQ(q16::from_ratio(-1, 2).round_int(), 0);  // ties up
  CHECK_EQ(q16::from_ratio(-3, 2).floor_int(), -2);
  CHECK_EQ((q16::from_ratio(5, 2).to<4>().raw), 40);
  CHECK_EQ((q16::from_raw(1).to<4>().raw), 0);
  CHECK_EQ((q16::from_int(1).to<30>().raw), 1 << 30);
  CHECK_EQ((q16::from_int(2).to<30>().raw), INT32_MAX);  // q30 holds [-2, 2)
  CHECK_EQ((Fixed<int32_t, 4>::from_int(1).to<16>().raw), 65536);
  CHECK_EQ(sat_add(q16::from_int(30000), q16::from_int(30000)).raw, INT32_MAX);
  CHECK_EQ(sat_mul(q16::from_int(300), q16::from_int(300)).raw, INT32_MAX);
  CHECK_EQ(sat_mul(q16::from_ratio(1, 2), q16::from_ratio(1, 2)).raw, 16384);
  // Multiplication against the double oracle: error <= 0.5 LSB.
  std::mt19937 rng(3);
  for (int it = 0; it < 10000; ++it) {
    q16 x = q16::from_raw(static_cast<int32_t>(rng()) >> 8), y = q16::from_raw(static_cast<int32_t>(rng()) >> 12);
    double exact = (x.raw / 65536.0) * (y.raw / 65536.0) * 65536.0;
    if (!CHECK_NEAR(static_cast<double>(sat_mul(x, y).raw), exact, 0.5)) break;
  }
}

TEST(fixed_mul_wide_paths_agree) {
  std::mt19937_64 rng(22);
  for (int it = 0; it < 100000; ++it) {
    const uint64_t a = rng() >> (rng() % 64), b = rng() >> (rng() % 64);
    const U128 fast = mul_wide_u64(a, b), portable = mul_wide_u64_portable(a, b);
    if (!CHECK_EQ(fast.hi, portable.hi) || !CHECK_EQ(fast.lo, portable.lo)) break;
  }
  const U128 top = mul_wide_u64_portable(UINT64_MAX, UINT64_MAX);  // (2^64 - 1)^2 = 2^128 - 2^65 + 1
  CHECK_EQ(top.hi, UINT64_MAX - 1);
  CHECK_EQ(top.lo, uint64_t{1});
}

TEST(fixed_mul_shift_paths_agree) {
  std::mt19937_64 rng(21);
  for (int it = 0; it < 100000; ++it) {
    int64_t a = static_cast<int64_t>(rng()) >> (rng() % 63), b = static_cast<int64_t>(rng()) >> (rng() % 63);
    int s = static_cast<int>(rng() % 64);
    if (!CHECK_EQ(mul_shift(a, b, s), mul_shift_portable(a, b, s))) break;
#ifdef __SIZEOF_INT128__
    __int128 q = (static_cast<__int128>(a) * b) >> s;
    int64_t want = q > INT64_MAX ? INT64_MAX : (q < INT64_MIN ? INT64_MIN : static_cast<int64_t>(q));
    if (!CHECK_EQ(mul_shift_portable(a, b, s), want)) break;
#endif
  }
  CHECK_EQ(mul_shift(-1, 1, 1), -1);  // floor, not truncation
  CHECK_EQ(mul_shift_portable(-1, 1, 1), -1);
  CHECK_EQ(mul_shift_portable(INT64_MIN, 1, 0), INT64_MIN);
  CHECK_EQ(mul_shift_portable(INT64_MIN, -1, 0), INT64_MAX);
}

// mul_shift_fit: the same bits as mul_shift whenever the result fits, on
// every path (the sweep's inner loops rely on it; see core/cut/sweep_piece.h).
TEST(fixed_mul_shift_fit_equals_mul_shift_when_it_fits) {
  std::mt19937_64 rng(22);
  int checked = 0;
  for (int it = 0; it < 200000; ++it) {
    const int64_t a = static_cast<int64_t>(rng()) >> (rng() % 63), b = static_cast<int64_t>(rng()) >> (rng() % 63);
    const int s = static_cast<int>(rng() % 64);
    const int64_t want = mul_shift(a, b, s);
    if (want == INT64_MAX || want == INT64_MIN) continue;  // saturated: outside the contract
    ++checked;
    if (!CHECK_EQ(mul_shift_fit(a, b, s), want)) break;
  }
  CHECK(checked > 100000);
  // The sweep's extreme ranges: rho * K, u * slope, a length times v_per_u.
  CHECK_EQ(mul_shift_fit(int64_t(1) << 30, (int64_t(1) << 55) - 1, 30), mul_shift(int64_t(1) << 30, (int64_t(1) << 55) - 1, 30));
  CHECK_EQ(mul_shift_fit(-(int64_t(1) << 31), (int64_t(1) << 62) - 1, 32),
           mul_shift(-(int64_t(1) << 31), (int64_t(1) << 62) - 1, 32));
  CHECK_EQ(mul_shift_fit(-1, 1, 1), -1);  // floor, not truncation
}

TEST(fixed_isqrt_fast_matches_exact) {
  std::mt19937_64 rng(31);
  for (int it = 0; it < 300000; ++it) {
    uint64_t v = rng() >> (rng() % 64);
    if (!CHECK_EQ(isqrt_fast_u64(v), isqrt_u64(v))) break;
  }
  for (uint64_t v = 0; v < 70000; ++v)
    if (!CHECK_EQ(isqrt_fast_u64(v), isqrt_u64(v))) break;
  const uint64_t edges[] = {UINT64_MAX, UINT64_MAX - 1, (uint64_t(1) << 62), (uint64_t(1) << 62) - 1,
                            0xfffffffe00000001ull, 0xfffffffe00000000ull, (uint64_t(1) << 32), (uint64_t(1) << 32) - 1};
  for (uint64_t v : edges) CHECK_EQ(isqrt_fast_u64(v), isqrt_u64(v));
  // Every exponent's normalisation: around each power of 4 and each square
  // of 2^k - 1 (the largest roots of that exponent).
  for (int e = 1; e < 32; ++e) {
    const uint64_t p4 = uint64_t(1) << (2 * e), top = ((uint64_t(1) << e) - 1) * ((uint64_t(1) << e) - 1);
    for (uint64_t v : {p4 - 1, p4, p4 + 1, top - 1, top, top + 1}) CHECK_EQ(isqrt_fast_u64(v), isqrt_u64(v));
  }
  for (uint64_t r = 1; r < (uint64_t(1) << 32); r = r * 3 + 1) {
    CHECK_EQ(isqrt_fast_u64(r * r), isqrt_u64(r * r));
    CHECK_EQ(isqrt_fast_u64(r * r - 1), isqrt_u64(r * r - 1));
  }
}
