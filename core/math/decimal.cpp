// Decimal text to exact integers; see decimal.h for the rounding contract.
#include "core/math/decimal.h"

#include "core/math/fixed.h"

namespace dexmill {

namespace {
inline bool is_blank(char c) { return c == ' ' || c == '\t'; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

int64_t pow10_i64(int k) {
  int64_t p = 1;
  for (int i = 0; i < k; ++i) p *= 10;
  return p;
}

DecimalParse decimal_parse(const char* s, size_t n, size_t* pos, Decimal* out) {
  size_t i = *pos;
  while (i < n && is_blank(s[i])) ++i;
  bool neg = false;
  if (i < n && (s[i] == '+' || s[i] == '-')) {
    neg = s[i] == '-';
    ++i;
  }
  int64_t mant = 0;
  int frac = 0;
  bool any = false, point = false, full = false;
  size_t end = i;
  for (; i < n; ++i) {
    char c = s[i];
    if (is_blank(c)) continue;
    if (c == '.' && !point) {
      point = true;
      end = i + 1;
      continue;
    }
    if (!is_digit(c)) break;
    any = true;
    end = i + 1;
    if (point) {
      // Fraction digits past what we keep only truncate (see decimal.h).
      if (full || frac >= kMaxFracDigits || mant > (kMaxMantissa - 1) / 10) {
        full = true;
        continue;
      }
      mant = mant * 10 + (c - '0');
      ++frac;
    } else {
      mant = mant * 10 + (c - '0');
      if (mant >= kMaxMantissa) return DecimalParse::kTooLarge;
    }
  }
  if (!any) return DecimalParse::kNoDigits;
  *pos = end;
  out->mant = neg ? -mant : mant;
  out->frac = static_cast<uint8_t>(frac);
  return DecimalParse::kOk;
}

int64_t decimal_scale(Decimal d, int64_t scale_num, int scale_den_pow10) {
  int den = d.frac + scale_den_pow10;
  // Cancel common powers of ten first so the divisor stays within 10^18.
  while (den > 0 && scale_num % 10 == 0) {
    scale_num /= 10;
    --den;
  }
  while (den > 18) {  // only when scale_num has no factor 10 left: drop digits
    d.mant /= 10;
    --den;
  }
  // Fast path: the product fits 64 bits (every coordinate does).
  int64_t prod;
  if (!__builtin_mul_overflow(d.mant, scale_num, &prod)) return den == 0 ? prod : div_round(prod, pow10_i64(den));
  return muldiv_round(d.mant, scale_num, pow10_i64(den));
}

bool decimal_to_int(Decimal d, int64_t* out) {
  int64_t p = pow10_i64(d.frac);
  if (d.mant % p != 0) return false;
  *out = d.mant / p;
  return true;
}

bool decimal_to_tenths(Decimal d, int64_t* out) {
  if (d.frac <= 1) {
    *out = d.frac == 1 ? d.mant : d.mant * 10;
    return true;
  }
  int64_t p = pow10_i64(d.frac - 1);
  if (d.mant % p != 0) return false;
  *out = d.mant / p;
  return true;
}

}  // namespace dexmill
