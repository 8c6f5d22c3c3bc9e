// pow_ratio.h's power as 2^(p log2(num / den)), in 64-bit words with 60
// fraction bits (q60) for the series and 56 (q56) for the logarithm that
// joins them. See pow_ratio.h for the bounds.
//
// - log2 v: v = 2^e m with m in [1/sqrt2, sqrt2), and log2 m = (2 / ln 2)
//   atanh(s) with s = (m - 1) / (m + 1), |s| <= 3 - 2 sqrt2 < 0.1716, by the
//   series atanh s = s (1 + s^2/3 + s^4/5 + ...): 11 terms leave s^23/23
//   (2^-61.4 in log2 m).
// - 2^f for f in [0, 1): sqrt2 e^u with u = (f - 1/2) ln 2, |u| < 0.3466, by
//   e^u = sum of u^k / k!: 14 terms leave u^14 / 14! (2^-61).
// The coefficients are round(2^60 / (2k + 1)) and round(2^60 / k!), computed
// here at compile time; Horner's rule with floored products (mul_shift) adds
// about a q60 unit a step. A q56 logarithm holds any log2(num / den) of
// uint64s (|log2| < 64, 64 2^56 = 2^62) to 2^-57, which in the exponent is a
// relative error of 2^-57 ln 2 p: far below the final rounding to q32.
// Right shifts of negative values are arithmetic (core/math/fixed.h relies
// on it too); nothing here shifts a negative value left.
#include "core/math/pow_ratio.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int kSeriesFracBits = 60;
constexpr int kLogFracBits = 56;
constexpr int64_t kOneQ60 = static_cast<int64_t>(1) << kSeriesFracBits;
constexpr int64_t kOneQ56 = static_cast<int64_t>(1) << kLogFracBits;
constexpr int64_t kOneQ32 = static_cast<int64_t>(1) << 32;
constexpr int64_t kPpmPerOne = 1000000;
// ln 2, 1 / ln 2 and sqrt 2 in q60, rounded to nearest; from 60-digit decimal
// arithmetic. tests/test_pow_ratio.cpp's bounds fail with a wrong digit.
constexpr int64_t kLn2Q60 = 799144290325165979LL;
constexpr int64_t kInvLn2Q60 = 1663314137230540311LL;
constexpr int64_t kSqrt2Q60 = 1630477228166597777LL;

constexpr int kAtanhTerms = 11;
constexpr int kExpTerms = 14;
// round(2^60 / (2k + 1)): the atanh series' coefficients of s^(2k+1).
struct AtanhSeries {
  int64_t q60[kAtanhTerms];
  constexpr AtanhSeries() : q60() {
    for (int k = 0; k < kAtanhTerms; ++k) q60[k] = (kOneQ60 + k) / (2 * k + 1);
  }
};
// round(2^60 / k!): the exponential series' coefficients of u^k.
struct ExpSeries {
  int64_t q60[kExpTerms];
  constexpr ExpSeries() : q60() {
    int64_t factorial = 1;  // 13! < 2^33
    for (int k = 0; k < kExpTerms; ++k) {
      if (k > 0) factorial *= k;
      q60[k] = (kOneQ60 + factorial / 2) / factorial;
    }
  }
};
constexpr AtanhSeries kAtanhSeries{};
constexpr ExpSeries kExpSeries{};

// round(v / 2^s) for 1 <= s < 63, ties up; |v| < 2^62.
inline int64_t round_shift(int64_t v, int s) { return (v + (static_cast<int64_t>(1) << (s - 1))) >> s; }

// log2 v = int_part + frac_q60 / 2^60 for v >= 1, frac in [-1/2, 1/2].
struct Log2Parts {
  int64_t int_part;
  int64_t frac_q60;
};

Log2Parts log2_parts(uint64_t v) {
  const int msb = 63 - __builtin_clzll(v);
  // v's top bit to bit 60: m = v / 2^msb in [1, 2) as q60. Bits below the 61
  // kept are dropped: at most 2^-60 relative, 1.3e-18 in the logarithm.
  const uint64_t m = msb > 60 ? v >> (msb - 60) : v << (60 - msb);
  // Above sqrt2 the same word read as q61 is m / 2, in (1/sqrt2, 1): the
  // exponent goes up by one and no bit is lost. `one` is 1 in m's scale.
  const bool halve = m > static_cast<uint64_t>(kSqrt2Q60);
  const int64_t one = halve ? 2 * kOneQ60 : kOneQ60;
  const int64_t mi = static_cast<int64_t>(m);  // < 2^61
  const int64_t s_q60 = muldiv_round(mi - one, kOneQ60, mi + one);
  const int64_t z_q60 = mul_shift(s_q60, s_q60, kSeriesFracBits);
  int64_t p_q60 = kAtanhSeries.q60[kAtanhTerms - 1];
  for (int k = kAtanhTerms - 2; k >= 0; --k) p_q60 = kAtanhSeries.q60[k] + mul_shift(p_q60, z_q60, kSeriesFracBits);
  const int64_t atanh_q60 = mul_shift(s_q60, p_q60, kSeriesFracBits);
  // log2 m = 2 atanh(s) / ln 2: one bit less of shift doubles the product.
  return Log2Parts{msb + (halve ? 1 : 0), mul_shift(atanh_q60, kInvLn2Q60, kSeriesFracBits - 1)};
}

// log2(num / den) in q56, num, den >= 1; |result| < 64 2^56.
int64_t log2_ratio_q56(uint64_t num, uint64_t den) {
  const Log2Parts a = log2_parts(num), b = log2_parts(den);
  const int64_t frac_q56 = round_shift(a.frac_q60 - b.frac_q60, kSeriesFracBits - kLogFracBits);
  return (a.int_part - b.int_part) * kOneQ56 + frac_q56;
}

// 2^(f / 2^56) in q60 for f_q56 in (0, 2^56): in (1, 2) but for the series'
// few units of error; held to 2 at most, so that 2^29 2^f stays within 2^62.
int64_t exp2_frac_q60(int64_t f_q56) {
  const int64_t u_q60 = mul_shift((f_q56 - kOneQ56 / 2) * 16, kLn2Q60, kSeriesFracBits);
  int64_t e_q60 = kExpSeries.q60[kExpTerms - 1];
  for (int k = kExpTerms - 2; k >= 0; --k) e_q60 = kExpSeries.q60[k] + mul_shift(e_q60, u_q60, kSeriesFracBits);
  return min_of(mul_shift(e_q60, kSqrt2Q60, kSeriesFracBits), 2 * kOneQ60);
}

// 2^(y / 2^56) in q32, rounded: 2^n 2^f with n = floor(y), f in [0, 1), is
// 2^f in q60 times 2^(n + 32 - 60). INT64_MAX above 2^62 (q32), 0 below 1.
int64_t exp2_from_q56(int64_t y_q56) {
  const int64_t n = y_q56 >> kLogFracBits;
  if (n >= 31) return INT64_MAX;
  if (n < -32) return 0;
  const int64_t f_q56 = y_q56 - n * kOneQ56;
  // f = 0 exactly: 2^n exactly, also at the top of the range (n = 30 gives
  // 2^62, the largest unsaturated result).
  const int64_t mant_q60 = f_q56 == 0 ? kOneQ60 : exp2_frac_q60(f_q56);
  if (n == 30) return mant_q60 > kOneQ60 ? INT64_MAX : 4 * mant_q60;
  if (n >= 28) return mant_q60 * (n == 29 ? 2 : 1);  // no fraction bits to drop
  return round_shift(mant_q60, static_cast<int>(28 - n));
}

}  // namespace

int64_t log2_ratio_q32(uint64_t num, uint64_t den) {
  if (num == 0 || den == 0) return num == den ? 0 : (num == 0 ? INT64_MIN : INT64_MAX);
  return round_shift(log2_ratio_q56(num, den), kLogFracBits - 32);
}

int64_t exp2_q32(int64_t x_q32) {
  // Outside [-33, 31) the result is saturated or 0 whatever the fraction;
  // inside, x in q56 fits (|x| < 33 2^56).
  if (x_q32 >= 31 * kOneQ32) return INT64_MAX;
  if (x_q32 < -33 * kOneQ32) return 0;
  return exp2_from_q56(x_q32 * (static_cast<int64_t>(1) << (kLogFracBits - 32)));
}

int64_t pow_ratio_q32(uint64_t num, uint64_t den, int32_t exp_ppm) {
  if (exp_ppm == 0 || num == den) return kOneQ32;
  if (num == 0 || den == 0) return (num == 0) == (exp_ppm < 0) ? INT64_MAX : 0;
  // p log2(num / den) in q56, rounded; it saturates only beyond |y| >= 128,
  // where 2^y is saturated or 0 anyway.
  return exp2_from_q56(muldiv_round(log2_ratio_q56(num, den), exp_ppm, kPpmPerOne));
}

}  // namespace dexmill
