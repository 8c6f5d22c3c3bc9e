// The numbers of RS274/NGC expressions and parameters, in fixed
// point: a value is e9 / 10^9 exactly, so that every number a program
// writes with up to 9 decimals is held exactly (G-code numbers are decimal;
// LinuxCNC holds them in doubles). |value| <= kGValueMax (10^9: a km in mm,
// a parameter count, a feed); a result beyond it is an error, never a wrap.
//
// Operations and their error bounds against exact arithmetic (tested
// against a double oracle in tests/test_gvalue.cpp), in units of the last
// place (ulp = 10^-9):
//   + - : exact.
//   * / : the exact result rounded to nearest (0.5 ulp).
//   MOD : exact (a - b floor(a / b), LinuxCNC's sign rule).
//   SQRT: 0.5 ulp.  FIX, FUP, ROUND, ABS: exact.
//   SIN, COS (degrees): 5 ulp (CORDIC, core/math/trig.h, and the degree to
//         binary-angle rounding).  TAN: 5 ulp relative to 1 + tan^2.
//   ATAN, ASIN, ACOS (degrees): 2e-7 degrees (CORDIC's 2 binary-angle units).
//   EXP: relative 3e-16 plus 0.5 ulp.  LN: 2 ulp.
//   ** : an integer exponent by repeated squaring, each product rounded
//        (0.5 ulp each, relative to the partial product); otherwise
//        EXP[b LN[a]].
// Comparisons follow LinuxCNC: EQ and NE with its tolerance 0.0001; GT,
// GE, LT, LE exact. AND, OR, XOR on "non-zero".
#ifndef DEXMILL_CORE_GCODE_GVALUE_H
#define DEXMILL_CORE_GCODE_GVALUE_H

#include <stdint.h>

#include "core/gcode/error.h"
#include "core/math/decimal.h"

namespace dexmill {

constexpr int64_t kGValueOne = 1000000000;                // 1.0
constexpr int64_t kGValueMax = kGValueOne * kGValueOne;   // e9 of 10^9

struct GValue {
  int64_t e9;
};

inline GValue gvalue_int(int64_t v) { return GValue{v * kGValueOne}; }

// A decimal as written (exact up to 9 decimals, rounded to nearest beyond);
// kExprOutOfRange beyond kGValueMax.
GcodeError gvalue_from_decimal(Decimal d, GValue* out);
// The value as a Decimal (9 decimals, trailing zeros dropped).
Decimal gvalue_to_decimal(GValue v);

enum class GBinary : uint8_t {
  kPower, kTimes, kDivide, kMod, kPlus, kMinus, kEq, kNe, kGt, kGe, kLt, kLe, kAnd, kOr, kXor,
};
// LinuxCNC's precedence: ** 6, * / MOD 5, + - 4, comparisons 3, AND OR XOR 2.
int gbinary_precedence(GBinary op);
// a op b; kOk, or kExprDivideByZero, kExprDomain, kExprOutOfRange.
GcodeError gvalue_binary(GBinary op, GValue a, GValue b, GValue* out);

enum class GUnary : uint8_t { kAbs, kAcos, kAsin, kCos, kExp, kFix, kFup, kLn, kRound, kSin, kSqrt, kTan };
GcodeError gvalue_unary(GUnary f, GValue a, GValue* out);
// ATAN[y]/[x], degrees in (-180, 180].
GValue gvalue_atan2(GValue y, GValue x);
// Degrees (e9) as a binary angle (2^32 a turn, core/math/trig.h): reduced to
// [0, 360) exactly, then rounded to nearest (0.5 bam, 7.3e-10 rad). SIN and
// COS go through it, and so do the polar words' angles (core/interp/polar.h).
uint32_t bam_of_degrees(int64_t deg_e9);

}  // namespace dexmill

#endif
