// Decimal numbers of G-code, read straight from text into integers (never
// through floating point; core/README.md "Numbers").
//
// A Decimal is mant / 10^frac exactly as written, with up to kMaxFracDigits
// fraction digits kept (further digits are dropped, i.e. the magnitude is
// truncated there) and |mant| < 10^17. Conversions to nanometres round to
// nearest, ties away from zero:
//   mm:   exact for up to 6 decimals (1 nm = 1e-6 mm);
//   inch: value * 25.4 mm; exact for up to 5 decimals (1e-5 in = 254 nm),
//         otherwise the nearest nm (correct for inputs with up to 12 decimals).
#ifndef DEXMILL_CORE_MATH_DECIMAL_H
#define DEXMILL_CORE_MATH_DECIMAL_H

#include <stddef.h>
#include <stdint.h>

namespace dexmill {

constexpr int kMaxFracDigits = 12;
constexpr int64_t kMaxMantissa = 100000000000000000;  // 10^17, exclusive

struct Decimal {
  int64_t mant;   // signed digits
  uint8_t frac;   // number of digits after the point, <= kMaxFracDigits
};

enum class DecimalParse : uint8_t {
  kOk = 0,
  kNoDigits = 1,   // no digit at all ("X", "X-", "X.")
  kTooLarge = 2,   // more integer digits than fit (|value| >= 10^17 / 10^frac)
};

// Reads [sign] digits [. digits] from s[*pos, n), skipping spaces and tabs
// anywhere (RS274/NGC ignores white space outside comments). On success
// *pos is just past the last character of the number.
DecimalParse decimal_parse(const char* s, size_t n, size_t* pos, Decimal* out);

// 10^k for 0 <= k <= 18.
int64_t pow10_i64(int k);

// round(value * scale_num / 10^scale_den_pow10) to nearest, ties away from
// zero, saturating to the int64 range. E.g. mm -> nm: (d, 1000000, 0).
int64_t decimal_scale(Decimal d, int64_t scale_num, int scale_den_pow10 = 0);

// Value in nm for a length in mm (inch == false) or inch (inch == true).
inline int64_t decimal_to_nm(Decimal d, bool inch) {
  return decimal_scale(d, inch ? 25400000 : 1000000);
}

// True if the value is a whole number; then *out is that number.
bool decimal_to_int(Decimal d, int64_t* out);

// The value times 10 when it has at most one decimal (G and M codes are
// kept in tenths, G38.2 = 382); false otherwise.
bool decimal_to_tenths(Decimal d, int64_t* out);

inline bool decimal_is_negative(Decimal d) { return d.mant < 0; }
inline bool decimal_is_zero(Decimal d) { return d.mant == 0; }

}  // namespace dexmill

#endif
