// core/math/pow_ratio.h against a floating-point oracle: the bounds stated in
// pow_ratio.h, over random and edge inputs and over Kienzle's range (chips of
// 0.001 mm to 10 mm, mc from 0.1 to 0.5). The oracle is std::pow, std::log2
// and std::exp2 in long double (64-bit mantissa on x86, where its own error
// is far below the bounds; where long double is double, its error is added
// to the tolerance, from its epsilon). Each case prints the worst errors.
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/math/pow_ratio.h"
#include "tests/rng.h"
#include "tests/runner.h"

using namespace dexmill;

namespace {

using ld = long double;
const ld kEps = std::numeric_limits<ld>::epsilon();
const ld kQ32 = 4294967296.0L;                // 2^32: one in q32
const ld kMaxQ32 = 4611686018427387904.0L;    // 2^62: the largest unsaturated result
const ld kRelBound = std::ldexp(1.0L, -53);   // pow_ratio.h: exp2_q32, pow_ratio_q32
const ld kLog2BoundUnits = 0.5L + std::ldexp(1.0L, -20);  // pow_ratio.h: log2_ratio_q32

// The worst errors seen: |got - exact| / exact, over results of 1 or more
// (below, the final rounding's half unit is most of it) and over all, and
// the part beyond that half unit, (|got - exact| - 1/2) / exact (what the
// series and the logarithm's rounding add; visible for large results).
struct Worst {
  ld rel = 0, rel_all = 0, excess = 0;
  void add(ld err_units, ld exact_units) {
    if (exact_units >= kQ32) rel = std::fmax(rel, err_units / exact_units);
    rel_all = std::fmax(rel_all, err_units / exact_units);
    excess = std::fmax(excess, (err_units - 0.5L) / exact_units);
  }
};

// A q32 result against the exact value in q32 units: saturated above 2^62,
// 0 allowed below one unit, otherwise within half a unit plus kRelBound
// (and the oracle's own relative error) of the exact value.
bool q32_within(int64_t got, ld exact_units, ld oracle_rel, Worst* w) {
  const ld tol = (kRelBound + oracle_rel) * exact_units;
  if (got != INT64_MAX && !CHECK_LE(static_cast<ld>(got), kMaxQ32)) return false;
  if (!CHECK_GE(got, 0)) return false;
  if (exact_units > kMaxQ32 + tol) return CHECK_EQ(got, INT64_MAX);
  if (got == INT64_MAX) return CHECK_GE(exact_units, kMaxQ32 - tol);
  if (got == 0 && exact_units < 1.0L + tol) return true;
  const ld err = std::fabs(static_cast<ld>(got) - exact_units);
  w->add(err, exact_units);
  return CHECK_LE(err, 0.5L + tol);
}

// log2(num / den) exactly enough: the ratio rounds once (relative kEps / 2),
// then log2 (an ulp of a result below 64).
ld log2_oracle(uint64_t num, uint64_t den) { return std::log2(static_cast<ld>(num) / static_cast<ld>(den)); }

bool log2_within(uint64_t num, uint64_t den, ld* worst_units) {
  const ld exact = log2_oracle(num, den);
  const ld oracle_units = 4 * kEps * (1 + std::fabs(exact)) * kQ32;
  const ld err = std::fabs(static_cast<ld>(log2_ratio_q32(num, den)) - exact * kQ32);
  *worst_units = std::fmax(*worst_units, err);
  if (err <= kLog2BoundUnits + oracle_units) return true;
  std::printf("log2_ratio_q32(%llu, %llu): got %lld, exact %.6Lf (q32 units)\n", static_cast<unsigned long long>(num),
              static_cast<unsigned long long>(den), static_cast<long long>(log2_ratio_q32(num, den)), exact * kQ32);
  return CHECK_LE(err, kLog2BoundUnits + oracle_units);
}

// pow_ratio_q32 against std::pow. The oracle's error: the ratio's and the
// exponent's roundings, the latter times |y| (y the exponent of 2).
bool pow_within(uint64_t num, uint64_t den, int32_t exp_ppm, Worst* w) {
  const ld x = static_cast<ld>(num) / static_cast<ld>(den), p = exp_ppm / 1e6L;
  const ld y = p * std::log2(x);
  const ld exact_units = std::pow(x, p) * kQ32;
  const int64_t got = pow_ratio_q32(num, den, exp_ppm);
  if (q32_within(got, exact_units, (4 + std::fabs(y)) * kEps, w)) return true;
  std::printf("pow_ratio_q32(%llu, %llu, %d): got %lld, exact %.3Lf (q32 units)\n", static_cast<unsigned long long>(num),
              static_cast<unsigned long long>(den), exp_ppm, static_cast<long long>(got), exact_units);
  return false;
}

bool exp2_within(int64_t x_q32, Worst* w) {
  const ld exact_units = std::exp2(static_cast<ld>(x_q32) / kQ32 + 32);
  const int64_t got = exp2_q32(x_q32);
  if (q32_within(got, exact_units, 4 * kEps, w)) return true;
  std::printf("exp2_q32(%lld): got %lld, exact %.3Lf (q32 units)\n", static_cast<long long>(x_q32),
              static_cast<long long>(got), exact_units);
  return false;
}

// A uint64 with a random number of bits, 1..64, its top bit set: every
// magnitude as often.
uint64_t log_uniform_u64(t::Rng& rng) {
  const int bits = 1 + static_cast<int>(rng.next() % 64);
  const uint64_t v = rng.next();
  return bits == 64 ? v | (static_cast<uint64_t>(1) << 63) : (v & ((static_cast<uint64_t>(1) << bits) - 1)) | (static_cast<uint64_t>(1) << (bits - 1));
}

const uint64_t kTop = static_cast<uint64_t>(1) << 63;

}  // namespace

TEST(pow_ratio_log2_edges) {
  CHECK_EQ(log2_ratio_q32(1, 1), 0);
  CHECK_EQ(log2_ratio_q32(1u << 24, 1), 24 * static_cast<int64_t>(1) << 32);
  CHECK_EQ(log2_ratio_q32(1, 1u << 24), -24 * (static_cast<int64_t>(1) << 32));
  CHECK_EQ(log2_ratio_q32(kTop, 1), 63 * (static_cast<int64_t>(1) << 32));
  CHECK_EQ(log2_ratio_q32(UINT64_MAX, 1), 64 * (static_cast<int64_t>(1) << 32));  // 64 - 7.8e-20, rounded
  CHECK_EQ(log2_ratio_q32(1, UINT64_MAX), -64 * (static_cast<int64_t>(1) << 32));
  CHECK_EQ(log2_ratio_q32(UINT64_MAX, UINT64_MAX), 0);
  CHECK_EQ(log2_ratio_q32(0, 5), INT64_MIN);
  CHECK_EQ(log2_ratio_q32(5, 0), INT64_MAX);
  CHECK_EQ(log2_ratio_q32(0, 0), 0);
  ld worst = 0;
  const uint64_t pairs[][2] = {
      {3, 7},           {7, 3},           {1, 3},          {3, 1},          {10, 1},          {1000, 1000000},
      {kTop - 1, kTop}, {kTop, kTop - 1}, {kTop - 1, 1},   {1, kTop - 1},   {UINT64_MAX, kTop}, {kTop + 1, kTop - 1},
      {UINT64_MAX - 1, UINT64_MAX},      {(kTop - 1) >> 24, kTop - 1},      {kTop - 1, (kTop - 1) >> 24},
      {3037000499u, 2147483648u},        {1414213562373095048u, 1000000000000000000u},  // about sqrt2: the halving
      {1414213562373095049u, 1000000000000000000u},
  };
  for (const auto& p : pairs) CHECK(log2_within(p[0], p[1], &worst));
  std::printf("log2_ratio_q32 edges: worst |error| %.9Lf q32 units (bound %.9Lf)\n", worst, kLog2BoundUnits);
}

TEST(pow_ratio_log2_random) {
  t::Rng rng(41);
  ld worst = 0;
  for (int it = 0; it < 200000; ++it) {
    const uint64_t num = log_uniform_u64(rng), den = log_uniform_u64(rng);
    if (!log2_within(num, den, &worst)) break;
  }
  // Every mantissa near 1 and near sqrt2, where the series' argument is 0
  // and largest and the reduction switches.
  for (uint64_t d = 0; d < 2000; ++d) {
    if (!log2_within(kTop + d, kTop, &worst) || !log2_within(kTop - d, kTop, &worst)) break;
    if (!log2_within(13043817825332782212u + d, kTop, &worst) || !log2_within(13043817825332782212u - d, kTop, &worst)) break;
  }
  std::printf("log2_ratio_q32: worst |error| %.9Lf q32 units (bound %.9Lf)\n", worst, kLog2BoundUnits);
}

TEST(pow_ratio_exp2) {
  const int64_t one = static_cast<int64_t>(1) << 32;
  CHECK_EQ(exp2_q32(0), one);
  CHECK_EQ(exp2_q32(one), 2 * one);
  CHECK_EQ(exp2_q32(-one), one / 2);
  CHECK_EQ(exp2_q32(-32 * one), 1);
  CHECK_EQ(exp2_q32(-32 * one - 1), 0);  // below 2^-32
  CHECK_EQ(exp2_q32(-40 * one), 0);
  CHECK_EQ(exp2_q32(INT64_MIN), 0);
  CHECK_EQ(exp2_q32(29 * one), static_cast<int64_t>(1) << 61);
  CHECK_EQ(exp2_q32(30 * one), static_cast<int64_t>(1) << 62);  // the largest result, exact
  CHECK_EQ(exp2_q32(30 * one + 1), INT64_MAX);
  CHECK_EQ(exp2_q32(40 * one), INT64_MAX);
  CHECK_EQ(exp2_q32(INT64_MAX), INT64_MAX);
  for (int n = -32; n <= 30; ++n) CHECK_EQ(exp2_q32(n * one), static_cast<int64_t>(1) << (n + 32));
  Worst w;
  t::Rng rng(42);
  const int64_t edges[] = {30 * one - 1, 29 * one - 1, 29 * one + 1, -32 * one + 1, -31 * one - 1, 1, -1, one / 2};
  for (int64_t x : edges) CHECK(exp2_within(x, &w));
  for (int it = 0; it < 400000; ++it) {
    if (!exp2_within(rng.range(-40 * one, 40 * one), &w)) break;
  }
  // Every fraction near 0, 1/2 and 1, where the series' argument is largest
  // or 0, at the top of the range.
  for (int64_t d = 1; d < 3000; ++d) {
    if (!exp2_within(29 * one + d, &w) || !exp2_within(30 * one - d, &w) || !exp2_within(29 * one + one / 2 + d - 1500, &w)) break;
  }
  std::printf("exp2_q32: worst relative error %.3Lg (results >= 1), beyond the half unit %.3Lg (bound %.3Lg + 1/2 unit)\n",
              w.rel, w.excess, kRelBound);
}

TEST(pow_ratio_kienzle) {
  // kc = kc1.1 (h / 1 mm)^-mc and the force's h^(1 - mc): h_nm from 1 um to
  // 10 mm, a step of 0.02 % (and every nm from 1000 to 3000), mc from 0.1 to 0.5.
  Worst kc, force;  // h^-mc (0.32 to 32) and h^(1 - mc) (0.002 to 7.9)
  t::Rng rng(43);
  const int32_t mcs[] = {100000, 170000, 250000, 260000, 333333, 420000, 500000};
  int cases = 0;
  for (ld h = 1000; h <= 10000000.0L; h *= 1.0002L) {
    const uint64_t h_nm = static_cast<uint64_t>(h);
    const int32_t mc_ppm = static_cast<int32_t>(rng.range(100000, 500000));
    const int32_t mc_fixed = mcs[cases % 7];
    if (!pow_within(h_nm, 1000000, -mc_ppm, &kc) || !pow_within(h_nm, 1000000, 1000000 - mc_ppm, &force)) break;
    if (!pow_within(h_nm, 1000000, -mc_fixed, &kc) || !pow_within(h_nm, 1000000, 1000000 - mc_fixed, &force)) break;
    cases += 4;
  }
  for (uint64_t h_nm = 1000; h_nm <= 3000; ++h_nm) {
    const int32_t mc_ppm = static_cast<int32_t>(rng.range(100000, 500000));
    if (!pow_within(h_nm, 1000000, -mc_ppm, &kc) || !pow_within(h_nm, 1000000, 1000000 - mc_ppm, &force)) break;
    cases += 2;
  }
  for (int32_t mc_ppm = 100000; mc_ppm <= 500000; mc_ppm += 1000) {
    CHECK(pow_within(1000, 1000000, -mc_ppm, &kc));
    CHECK(pow_within(10000000, 1000000, -mc_ppm, &kc));
    CHECK(pow_within(1000, 1000000, 1000000 - mc_ppm, &force));
    CHECK(pow_within(10000000, 1000000, 1000000 - mc_ppm, &force));
    cases += 4;
  }
  // 1 mm: kc is kc1.1 exactly.
  CHECK_EQ(pow_ratio_q32(1000000, 1000000, -250000), static_cast<int64_t>(1) << 32);
  std::printf("pow_ratio_q32 Kienzle (%d cases): worst relative error h^-mc %.3Lg, h^(1-mc) %.3Lg; beyond the half unit "
              "%.3Lg and %.3Lg (bound %.3Lg + 1/2 unit)\n",
              cases, kc.rel_all, force.rel_all, kc.excess, force.excess, kRelBound);
  // All results counted, the half unit at the smallest: 10^-0.5 = 0.32
  // (half of 2^-32 is 3.7e-10 of it) and 0.001^0.9 = 0.002 (5.8e-8).
  CHECK_LE(kc.rel_all, 4e-10L);
  CHECK_LE(force.rel_all, 6e-8L);
}

TEST(pow_ratio_domain) {
  const int64_t one = static_cast<int64_t>(1) << 32;
  const uint64_t r24 = static_cast<uint64_t>(1) << 24;
  CHECK_EQ(pow_ratio_q32(4, 1, 1000000), 4 * one);
  CHECK_EQ(pow_ratio_q32(4, 1, 500000), 2 * one);
  CHECK_EQ(pow_ratio_q32(1, 4, 500000), one / 2);
  CHECK_EQ(pow_ratio_q32(r24, 1, 1250000), static_cast<int64_t>(1) << 62);  // 2^30 exactly: not saturated
  CHECK_EQ(pow_ratio_q32(r24, 1, 1250001), INT64_MAX);
  CHECK_EQ(pow_ratio_q32(r24, 1, 2000000), INT64_MAX);
  CHECK_EQ(pow_ratio_q32(1, r24, 2000000), 0);  // 2^-48
  CHECK_EQ(pow_ratio_q32(r24, 1, -2000000), 0);
  CHECK_EQ(pow_ratio_q32(1, r24, -1250000), static_cast<int64_t>(1) << 62);
  CHECK_EQ(pow_ratio_q32(1, r24, 1333334), 0);   // just below 2^-32
  CHECK_EQ(pow_ratio_q32(1, r24, 1333333), 1);   // 2^-31.99999
  CHECK_EQ(pow_ratio_q32(kTop, kTop >> 24, -1000000), one >> 24);
  CHECK_EQ(pow_ratio_q32(UINT64_MAX, UINT64_MAX, 2000000), one);
  CHECK_EQ(pow_ratio_q32(7, 3, 0), one);
  CHECK_EQ(pow_ratio_q32(0, 3, 500000), 0);
  CHECK_EQ(pow_ratio_q32(0, 3, -500000), INT64_MAX);
  CHECK_EQ(pow_ratio_q32(3, 0, 500000), INT64_MAX);
  CHECK_EQ(pow_ratio_q32(3, 0, -500000), 0);
  CHECK_EQ(pow_ratio_q32(0, 0, 500000), one);
  CHECK_EQ(pow_ratio_q32(UINT64_MAX, 1, INT32_MAX), INT64_MAX);  // beyond the domain: saturates
  CHECK_EQ(pow_ratio_q32(UINT64_MAX, 1, INT32_MIN), 0);
  Worst w;
  const uint64_t nums[][2] = {{r24, 1}, {1, r24}, {kTop - 1, (kTop - 1) >> 24}, {(kTop - 1) >> 24, kTop - 1},
                              {kTop - 1, kTop - 2}, {UINT64_MAX, UINT64_MAX - 1}, {3, 7}, {7, 3}};
  const int32_t exps[] = {-2000000, -1999999, -1000000, -500000, -1, 1, 500000, 1000000, 1249999, 1999999, 2000000};
  for (const auto& nd : nums) {
    for (int32_t e : exps) CHECK(pow_within(nd[0], nd[1], e, &w));
  }
  // Random ratios in [2^-24, 2^24] of numbers of any size, any exponent.
  t::Rng rng(44);
  int cases = 0;
  while (cases < 200000) {
    const uint64_t num = log_uniform_u64(rng), den = log_uniform_u64(rng);
    const ld l = std::log2(static_cast<ld>(num) / static_cast<ld>(den));
    if (l < -24 || l > 24) continue;
    if (!pow_within(num, den, static_cast<int32_t>(rng.range(-2000000, 2000000)), &w)) break;
    ++cases;
  }
  std::printf("pow_ratio_q32 domain: worst relative error %.3Lg (results >= 1), beyond the half unit %.3Lg (bound %.3Lg + 1/2 unit)\n",
              w.rel, w.excess, kRelBound);
}
