// Table-and-Newton reciprocal and reciprocal square root (see approx.h).
#include "display/raster/approx.h"

namespace dexmill {
namespace {

// Initial estimates in q30 for the 256 intervals of the normalised argument,
// taken at each interval's midpoint; constexpr, so the tables are data in
// flash and need no start-up code.
struct RecipTable {
  uint32_t v[256];
  constexpr RecipTable() : v() {
    // a/2^32 in [0.5 + k/512, 0.5 + (k+1)/512): 1/x at the midpoint is
    // 512 / (256.5 + k), in q30 2^40 / (513 + 2k).
    for (int k = 0; k < 256; ++k) v[k] = static_cast<uint32_t>((static_cast<uint64_t>(1) << 40) / (513 + 2 * k));
  }
};

constexpr uint64_t isqrt_const(uint64_t x) {
  uint64_t r = 0;
  for (int b = 31; b >= 0; --b) {
    const uint64_t t = r | (static_cast<uint64_t>(1) << b);
    if (t * t <= x) r = t;
  }
  return r;
}

struct RsqrtTable {
  uint32_t v[192];
  constexpr RsqrtTable() : v() {
    // a/2^32 in [b/256, (b+1)/256), b = 64..255: 1/sqrt(x) at the midpoint is
    // 16 / sqrt(b + 0.5); in q30 sqrt(2^68 / (b + 0.5)) = sqrt(2^69 / (2b+1)),
    // computed as sqrt(2^63 / (2b+1)) * 8 (the table only seeds Newton).
    for (int b = 64; b < 256; ++b)
      v[b - 64] = static_cast<uint32_t>(isqrt_const((static_cast<uint64_t>(1) << 63) / (2 * b + 1)) * 8);
  }
};

constexpr RecipTable kRecip;
constexpr RsqrtTable kRsqrt;

}  // namespace

ScaledRecip recip_u32(uint32_t v) {
  if (v == 0) v = 1;
  const int n = __builtin_clz(v);
  const uint64_t a = static_cast<uint64_t>(v) << n;  // [2^31, 2^32): x = a / 2^32 in [0.5, 1)
  uint64_t y = kRecip.v[(a >> 23) & 0xFF];            // q30 estimate of 1/x, relative error < 2^-9
  for (int it = 0; it < 2; ++it) {
    // y' = y (2 - x y): x*y in q62 stays below 2^63, so 2 - x y is non-negative.
    const uint64_t xy = a * y;
    const uint64_t two_minus = ((static_cast<uint64_t>(1) << 63) - xy) >> 32;  // q30
    y = (y * two_minus) >> 30;
  }
  // 1/v = 2^n / a = (2^32 / a) * 2^(n - 32) = y * 2^(n - 62).
  if (y > (static_cast<uint64_t>(1) << 31)) y = static_cast<uint64_t>(1) << 31;
  return ScaledRecip{static_cast<uint32_t>(y), 62 - n};
}

namespace {

// Newton steps y' = y (3 - x y^2) / 2 on the table's estimate.
inline ScaledRecip rsqrt_steps(uint32_t v, int steps) {
  if (v == 0) v = 1;
  const int n = __builtin_clz(v) & ~1;                // even, so sqrt(2^n) is exact
  const uint64_t a = static_cast<uint64_t>(v) << n;  // [2^30, 2^32): x = a / 2^32 in [0.25, 1)
  uint64_t y = kRsqrt.v[(a >> 24) - 64];              // q30 estimate of 1/sqrt(x)
  for (int it = 0; it < steps; ++it) {
    const uint64_t y2 = (y * y) >> 30;               // q30, <= 2^32
    const uint64_t xy2 = (a * y2) >> 32;              // q30, about 2^30
    const uint64_t three_minus = (static_cast<uint64_t>(3) << 30) - xy2;
    y = (y * three_minus) >> 31;
  }
  // 1/sqrt(v) = 2^(n/2) / sqrt(a) = 2^(n/2) * y / 2^16 / 2^30.
  if (y > (static_cast<uint64_t>(1) << 31)) y = static_cast<uint64_t>(1) << 31;
  return ScaledRecip{static_cast<uint32_t>(y), 46 - n / 2};
}

}  // namespace

ScaledRecip rsqrt_u32(uint32_t v) { return rsqrt_steps(v, 2); }
ScaledRecip rsqrt_fast_u32(uint32_t v) { return rsqrt_steps(v, 1); }

UnitQ14 normal_unit_q14(int64_t x, int64_t y, int64_t z) {
  // Scale down so the largest component has 15 bits: the squares then sum
  // below 2^32 and the rest of the work is 32x32 -> 64 multiplies.
  uint64_t mx = 0;
  const int64_t c[3] = {x, y, z};
  for (int64_t v : c) {
    const uint64_t a = v < 0 ? 0u - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
    mx = mx > a ? mx : a;
  }
  if (mx == 0) return UnitQ14{0, 0, 16384};
  const int bits = 64 - __builtin_clzll(mx);
  const int sh = bits > 15 ? bits - 15 : 0;
  int64_t s[3];
  uint32_t len2 = 0;
  for (int k = 0; k < 3; ++k) {
    // Round to nearest so the direction error stays symmetric.
    s[k] = sh ? (c[k] >> sh) + ((c[k] >> (sh - 1)) & 1) : c[k];
    len2 += static_cast<uint32_t>(s[k] * s[k]);
  }
  if (len2 == 0) return UnitQ14{0, 0, 16384};
  ScaledRecip r = rsqrt_u32(len2);
  r.shift -= 14;  // result in q14
  return UnitQ14{static_cast<int32_t>(scale_recip(s[0], r)), static_cast<int32_t>(scale_recip(s[1], r)),
                 static_cast<int32_t>(scale_recip(s[2], r))};
}

}  // namespace dexmill
