// Fixed-point expression numbers; see gvalue.h.
#include "core/gcode/gvalue.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"
#include "core/math/wide.h"

namespace dexmill {
namespace {

// ln 2 and ln 10 in Q56 (2^56 = 72 057 594 037 927 936), rounded.
constexpr int64_t kLn2Q56 = 49946518145322874;
constexpr int64_t kLn10Q56 = 165918741868749488;
constexpr int kQ = 56;
constexpr int64_t kOneQ56 = static_cast<int64_t>(1) << kQ;
constexpr int64_t kTolEqualE9 = 100000;  // LinuxCNC's TOLERANCE_EQUAL, 0.0001
constexpr int64_t kFullTurnE9 = 360 * kGValueOne;

inline bool in_range(int64_t v) { return v >= -kGValueMax && v <= kGValueMax; }

GcodeError ranged(int64_t v, GValue* out) {
  if (!in_range(v)) return GcodeError::kExprOutOfRange;
  out->e9 = v;
  return GcodeError::kOk;
}

GValue truth(bool b) { return GValue{b ? kGValueOne : 0}; }

// A binary angle (2^32 a turn) as degrees in (-180, 180], e9 (a half turn
// is +180, as atan2 gives it).
int64_t degrees_of_bam(uint32_t bam) {
  const int64_t signed_bam = bam == kBamHalfTurn ? static_cast<int64_t>(kBamHalfTurn) : static_cast<int32_t>(bam);
  return muldiv_round(signed_bam, kFullTurnE9, static_cast<int64_t>(1) << 32);
}

int64_t e9_of_q30(int32_t q30) { return muldiv_round(q30, kGValueOne, static_cast<int64_t>(1) << 30); }

// exp(x) for x in Q56 with |x| < 22: e^r 2^k, r = x - k ln 2 in [-0.35,
// 0.35], e^r by its Taylor series to 2^-56.
GcodeError exp_q56(int64_t x_q56, GValue* out) {
  const int64_t k = div_round(x_q56, kLn2Q56);
  const int64_t r = x_q56 - k * kLn2Q56;
  int64_t sum = kOneQ56, term = kOneQ56;
  for (int n = 1; n < 24 && term != 0; ++n) {
    term = mul_shift(term, r, kQ) / n;
    sum += term;
  }
  if (k > 30) return GcodeError::kExprOutOfRange;
  if (k >= 0) return ranged(muldiv_round(sum, kGValueOne << k, kOneQ56), out);
  if (k < -40) {
    out->e9 = 0;
    return GcodeError::kOk;
  }
  // sum 10^9 / 2^(56 - k), in two steps that both fit.
  out->e9 = div_round(muldiv_round(sum, kGValueOne, kOneQ56 >> 16), static_cast<int64_t>(1) << (16 - k));
  return GcodeError::kOk;
}

// ln of the value a (e9, a > 0) in Q56: ln(a) - 9 ln 10 with a = m 2^k,
// m in [1, 2), ln m = 2 atanh((m - 1) / (m + 1)) by its series.
int64_t ln_q56(int64_t a) {
  int k = 0;
  while ((a >> (k + 1)) != 0) ++k;                     // 2^k <= a < 2^(k+1)
  const int64_t m = a << (61 - k);                     // Q61, [2^61, 2^62)
  const int64_t one = static_cast<int64_t>(1) << 61;
  const int64_t t = muldiv_floor(m - one, one, m + one);  // Q61, [0, 1/3)
  const int64_t t2 = mul_shift(t, t, 61);
  int64_t s = 0, pw = t;
  for (int n = 1; n < 80 && pw != 0; n += 2) {
    s += pw / n;
    pw = mul_shift(pw, t2, 61);
  }
  return (2 * s >> 5) + k * kLn2Q56 - 9 * kLn10Q56;
}

GcodeError power(GValue a, GValue b, GValue* out) {
  if (b.e9 % kGValueOne == 0) {
    int64_t n = b.e9 / kGValueOne;
    if (n == 0) return ranged(kGValueOne, out);  // LinuxCNC: pow(x, 0) = 1
    if (a.e9 == 0) {
      if (n < 0) return GcodeError::kExprDivideByZero;
      out->e9 = 0;
      return GcodeError::kOk;
    }
    const bool invert = n < 0;
    uint64_t e = static_cast<uint64_t>(invert ? -n : n);
    // Repeated squaring, each product rounded; beyond the range is an error
    // (or, inverted, a result that rounds to 0).
    int64_t result = kGValueOne, base = a.e9;
    bool big = false;
    while (e) {
      if (e & 1) {
        result = muldiv_round(result, base, kGValueOne);
        if (!in_range(result)) big = true;
      }
      e >>= 1;
      if (e) {
        base = muldiv_round(base, base, kGValueOne);
        if (!in_range(base)) big = true;
      }
      if (big) break;
    }
    if (!invert) return big ? GcodeError::kExprOutOfRange : ranged(result, out);
    if (big) {
      out->e9 = 0;
      return GcodeError::kOk;
    }
    if (result == 0) return GcodeError::kExprDivideByZero;
    return ranged(muldiv_round(kGValueOne, kGValueOne, result), out);
  }
  // A non-integer exponent: a must be positive (LinuxCNC: "Attempt to raise
  // negative to non-integer power"), 0 to a positive power is 0.
  if (a.e9 < 0) return GcodeError::kExprDomain;
  if (a.e9 == 0) {
    if (b.e9 < 0) return GcodeError::kExprDivideByZero;
    out->e9 = 0;
    return GcodeError::kOk;
  }
  const int64_t x = mul_shift(ln_q56(a.e9), muldiv_round(b.e9, static_cast<int64_t>(1) << 40, kGValueOne), 40);
  if (x > 22 * kOneQ56) return GcodeError::kExprOutOfRange;
  if (x < -41 * kOneQ56) {
    out->e9 = 0;
    return GcodeError::kOk;
  }
  return exp_q56(x, out);
}

}  // namespace

GcodeError gvalue_from_decimal(Decimal d, GValue* out) {
  int64_t v;
  if (d.frac <= 9) {
    if (__builtin_mul_overflow(d.mant, pow10_i64(9 - d.frac), &v)) return GcodeError::kExprOutOfRange;
  } else {
    v = div_round(d.mant, pow10_i64(d.frac - 9));
  }
  return ranged(v, out);
}

Decimal gvalue_to_decimal(GValue v) {
  Decimal d{v.e9, 9};
  while (d.frac > 0 && (d.mant >= kMaxMantissa || d.mant <= -kMaxMantissa)) {
    d.mant = div_round(d.mant, 10);
    --d.frac;
  }
  while (d.frac > 0 && d.mant % 10 == 0) {
    d.mant /= 10;
    --d.frac;
  }
  return d;
}

int gbinary_precedence(GBinary op) {
  switch (op) {
    case GBinary::kPower: return 6;
    case GBinary::kTimes: case GBinary::kDivide: case GBinary::kMod: return 5;
    case GBinary::kPlus: case GBinary::kMinus: return 4;
    case GBinary::kAnd: case GBinary::kOr: case GBinary::kXor: return 2;
    default: return 3;
  }
}

GcodeError gvalue_binary(GBinary op, GValue a, GValue b, GValue* out) {
  int64_t v = 0;
  switch (op) {
    case GBinary::kPower: return power(a, b, out);
    case GBinary::kTimes: return ranged(muldiv_round(a.e9, b.e9, kGValueOne), out);
    case GBinary::kDivide:
      if (b.e9 == 0) return GcodeError::kExprDivideByZero;
      return ranged(muldiv_round(a.e9, kGValueOne, b.e9), out);
    case GBinary::kMod: {
      if (b.e9 == 0) return GcodeError::kExprDivideByZero;
      int64_t r = a.e9 % b.e9;
      if (r < 0) r += b.e9 < 0 ? -b.e9 : b.e9;
      out->e9 = r;
      return GcodeError::kOk;
    }
    case GBinary::kPlus:
      if (__builtin_add_overflow(a.e9, b.e9, &v)) return GcodeError::kExprOutOfRange;
      return ranged(v, out);
    case GBinary::kMinus:
      if (__builtin_sub_overflow(a.e9, b.e9, &v)) return GcodeError::kExprOutOfRange;
      return ranged(v, out);
    case GBinary::kEq: *out = truth((a.e9 > b.e9 ? a.e9 - b.e9 : b.e9 - a.e9) < kTolEqualE9); break;
    case GBinary::kNe: *out = truth((a.e9 > b.e9 ? a.e9 - b.e9 : b.e9 - a.e9) >= kTolEqualE9); break;
    case GBinary::kGt: *out = truth(a.e9 > b.e9); break;
    case GBinary::kGe: *out = truth(a.e9 >= b.e9); break;
    case GBinary::kLt: *out = truth(a.e9 < b.e9); break;
    case GBinary::kLe: *out = truth(a.e9 <= b.e9); break;
    case GBinary::kAnd: *out = truth(a.e9 != 0 && b.e9 != 0); break;
    case GBinary::kOr: *out = truth(a.e9 != 0 || b.e9 != 0); break;
    case GBinary::kXor: *out = truth((a.e9 != 0) != (b.e9 != 0)); break;
  }
  return GcodeError::kOk;
}

uint32_t bam_of_degrees(int64_t deg_e9) {
  int64_t m = deg_e9 % kFullTurnE9;
  if (m < 0) m += kFullTurnE9;
  return static_cast<uint32_t>(static_cast<uint64_t>(muldiv_round(m, static_cast<int64_t>(1) << 32, kFullTurnE9)));
}

GValue gvalue_atan2(GValue y, GValue x) { return GValue{degrees_of_bam(atan2_bam(y.e9, x.e9))}; }

GcodeError gvalue_unary(GUnary f, GValue a, GValue* out) {
  switch (f) {
    case GUnary::kAbs: out->e9 = a.e9 < 0 ? -a.e9 : a.e9; return GcodeError::kOk;
    case GUnary::kFix: out->e9 = div_floor(a.e9, kGValueOne) * kGValueOne; return GcodeError::kOk;
    case GUnary::kFup: out->e9 = div_ceil(a.e9, kGValueOne) * kGValueOne; return GcodeError::kOk;
    case GUnary::kRound: out->e9 = div_round(a.e9, kGValueOne) * kGValueOne; return GcodeError::kOk;
    case GUnary::kSqrt: {
      if (a.e9 < 0) return GcodeError::kExprDomain;
      // sqrt(a 10^9) rounded: floor(2 sqrt(v)) = isqrt(4 v), then halved up.
      const uint64_t s = isqrt_u128(mul_wide_u64(static_cast<uint64_t>(a.e9), 4 * static_cast<uint64_t>(kGValueOne)));
      out->e9 = static_cast<int64_t>((s + 1) / 2);
      return GcodeError::kOk;
    }
    case GUnary::kSin: case GUnary::kCos: case GUnary::kTan: {
      const SinCosQ30 sc = sincos_bam(bam_of_degrees(a.e9));
      if (f == GUnary::kSin) out->e9 = e9_of_q30(sc.sin_q30);
      else if (f == GUnary::kCos) out->e9 = e9_of_q30(sc.cos_q30);
      else if (sc.cos_q30 == 0) return GcodeError::kExprOutOfRange;
      else return ranged(muldiv_round(sc.sin_q30, kGValueOne, sc.cos_q30), out);
      return GcodeError::kOk;
    }
    case GUnary::kAsin: case GUnary::kAcos: {
      if (a.e9 > kGValueOne || a.e9 < -kGValueOne) return GcodeError::kExprDomain;
      // The other leg of the right triangle with hypotenuse 1.
      const U128 one2 = mul_wide_u64(static_cast<uint64_t>(kGValueOne), static_cast<uint64_t>(kGValueOne));
      const int64_t leg = static_cast<int64_t>(isqrt_u128(sub_u128(one2, sq_u128(a.e9))));
      out->e9 = f == GUnary::kAsin ? degrees_of_bam(atan2_bam(a.e9, leg)) : degrees_of_bam(atan2_bam(leg, a.e9));
      return GcodeError::kOk;
    }
    case GUnary::kExp: {
      if (a.e9 > 22 * kGValueOne) return GcodeError::kExprOutOfRange;
      if (a.e9 < -41 * kGValueOne) {
        out->e9 = 0;
        return GcodeError::kOk;
      }
      return exp_q56(muldiv_round(a.e9, kOneQ56, kGValueOne), out);
    }
    case GUnary::kLn:
      if (a.e9 <= 0) return GcodeError::kExprDomain;
      out->e9 = muldiv_round(ln_q56(a.e9), kGValueOne, kOneQ56);
      return GcodeError::kOk;
  }
  return GcodeError::kOk;
}

}  // namespace dexmill
