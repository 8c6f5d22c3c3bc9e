// Integer powers of a ratio, for Kienzle's cutting-force law kc = kc1.1 h^-mc
// (core/engage/engage_load.h): (num / den)^(exp_ppm / 10^6) as
// 2^(exp_ppm / 10^6 * log2(num / den)), both halves fixed point (pow_ratio.cpp
// gives the series). Results are q32, i.e. the value times 2^32.
//
// Error bounds (checked against a long double oracle in
// tests/test_pow_ratio.cpp, which prints the worst errors it finds):
//   log2_ratio_q32: |result - exact| <= 1/2 q32 unit + 2^-20 unit, for every
//                   num, den >= 1; measured 0.5 + 2.3e-8 unit.
//   exp2_q32:       |result - exact| <= 2^-50 exact + 1/2 q32 unit; measured
//                   excess over the half unit 4.4e-18 exact.
//   pow_ratio_q32:  |result - exact| <= 2^-50 exact + 1/2 q32 unit (8.9e-16,
//                   far inside 2e-6) for a ratio in [2^-24, 2^24] and exp_ppm
//                   in [-2000000, 2000000]; measured excess 2.8e-17 exact.
//                   Over Kienzle's range (h 0.001 mm to 10 mm, mc 0.1 to 0.5)
//                   the half unit dominates: at most 3.7e-10 relative.
// Saturation: a result above 2^62 (q32, i.e. above 2^30) is INT64_MAX; one
// below 1 (q32, below 2^-32) is 0. An exact power of two (an integer exponent
// of 2) is exact.
//
// All integer, the same bits on every CPU: 64-bit words whose products go
// through mul_shift and muldiv_round (core/math/fixed.h), so a 32-bit CPU
// needs no 128-bit integers. Cost: two divisions of a 128-bit product (one per
// logarithm) and about 40 mul_shift products a call; set-up code, not for
// inner loops.
#ifndef DEXMILL_CORE_MATH_POW_RATIO_H
#define DEXMILL_CORE_MATH_POW_RATIO_H

#include <stdint.h>

namespace dexmill {

// (num / den)^(exp_ppm / 10^6) in q32, rounded. num, den >= 1 (outside that:
// 1 for exp_ppm 0 or num == den, else num 0 is a ratio of 0 and den 0 one of
// infinity, giving 0 or INT64_MAX). Any exp_ppm; the bounds above hold for
// ratios in [2^-24, 2^24] and exp_ppm in [-2000000, 2000000].
int64_t pow_ratio_q32(uint64_t num, uint64_t den, int32_t exp_ppm);

// log2(num / den) in q32 (signed), rounded; |result| <= 64 2^32. num 0 gives
// INT64_MIN, den 0 INT64_MAX, both 0 give 0.
int64_t log2_ratio_q32(uint64_t num, uint64_t den);

// 2^(x_q32 / 2^32) in q32, rounded; saturating and 0 as above.
int64_t exp2_q32(int64_t x_q32);

}  // namespace dexmill

#endif
