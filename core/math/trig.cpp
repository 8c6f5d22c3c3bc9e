// CORDIC in rotation mode (sincos) and vectoring mode (atan2), 30 steps in
// 64-bit intermediates. See trig.h for the error bounds.
#include "core/math/trig.h"

#include "core/math/fixed.h"

namespace dexmill {
namespace {

constexpr int kSteps = 30;
// atan(2^-i) in binary angles with 8 more fraction bits (2^40 per turn),
// rounded to nearest; generated offline with 50-digit decimal arithmetic.
// The extra bits keep the table's rounding from adding up over 31 steps.
// tests/test_trig.cpp checks every entry against double precision.
constexpr int64_t kAtanBamQ8[kSteps + 1] = {
    137438953472LL, 81134951838LL, 42869480287LL, 21761217566LL, 10922836750LL, 5466743129LL,
    2734038620LL,   1367102738LL,  683561799LL,   341782203LL,   170891265LL,   85445653LL,
    42722829LL,     21361415LL,    10680707LL,    5340354LL,     2670177LL,     1335088LL,
    667544LL,       333772LL,      166886LL,      83443LL,       41722LL,       20861LL,
    10430LL,        5215LL,        2608LL,        1304LL,        652LL,         326LL,
    163LL};
// 1/K of the CORDIC gain over kSteps + 1 steps, in q60 (the iteration runs
// with 60 fraction bits so that the shifted terms stay exact down to the last
// step): 0.607252935008881256257... * 2^60.
constexpr int64_t kInvGainQ60 = 700114967507363239LL;

// v, or -v when flip = -1 (flip = 0 or -1): a CORDIC step's turn direction
// is data, and as a branch about half of them mispredict.
inline int64_t negate_if(int64_t v, int64_t flip) { return (v ^ flip) - flip; }

}  // namespace

SinCosQ30 sincos_bam(uint32_t angle_bam) {
  // Fold into [-90, +90] degrees, where CORDIC converges; remember the sign.
  int64_t negate = 1;
  uint32_t a = angle_bam;
  if (a > kBamQuarterTurn && a < 3u * kBamQuarterTurn) {
    a += kBamHalfTurn;
    negate = -1;
  }
  int64_t z = static_cast<int64_t>(static_cast<int32_t>(a)) * 256;  // signed residual, bam q8
  int64_t x = kInvGainQ60, y = 0;
  for (int i = 0; i <= kSteps; ++i) {
    // Turn by +atan(2^-i) when z >= 0, else by -atan(2^-i).
    const int64_t flip = -static_cast<int64_t>(z < 0);
    const int64_t dx = negate_if(x >> i, flip), dy = negate_if(y >> i, flip);
    x -= dy;
    y += dx;
    z -= negate_if(kAtanBamQ8[i], flip);
  }
  // q60 -> q30, rounded to nearest.
  const int64_t half = static_cast<int64_t>(1) << 29;
  SinCosQ30 r;
  r.cos_q30 = static_cast<int32_t>(clamp<int64_t>(negate * ((x + half) >> 30), -(1 << 30), 1 << 30));
  r.sin_q30 = static_cast<int32_t>(clamp<int64_t>(negate * ((y + half) >> 30), -(1 << 30), 1 << 30));
  return r;
}

uint32_t atan2_bam(int64_t y, int64_t x) {
  if (x == 0 && y == 0) return 0;
  // Normalise so that the larger component lies in [2^55, 2^56): enough bits
  // for the last CORDIC step, headroom for the gain (1.65) and the sign.
  // (One shift by the distance to bit 55: the same as shifting a bit at a
  // time, since arithmetic shifts compose: (v >> 1) >> 1 == v >> 2.)
  const uint64_t m = abs_u64(x) | abs_u64(y);
  const int msb = 63 - __builtin_clzll(m);
  int64_t vx = x, vy = y;
  if (msb > 55) {
    vx >>= msb - 55;
    vy >>= msb - 55;
  } else {
    vx *= static_cast<int64_t>(1) << (55 - msb);  // |v| < 2^56 after: no overflow
    vy *= static_cast<int64_t>(1) << (55 - msb);
  }
  uint32_t base = 0;
  if (vx < 0) {  // rotate by 180 degrees into the right half-plane
    vx = -vx;
    vy = -vy;
    base = kBamHalfTurn;
  }
  int64_t z = 0;
  for (int i = 0; i <= kSteps; ++i) {
    // Turn towards the x axis: by -atan(2^-i) when vy > 0, else by +.
    const int64_t flip = -static_cast<int64_t>(vy <= 0);
    const int64_t dx = negate_if(vx >> i, flip), dy = negate_if(vy >> i, flip);
    vx += dy;
    vy -= dx;
    z += negate_if(kAtanBamQ8[i], flip);
  }
  return base + static_cast<uint32_t>(static_cast<int32_t>(div_round(z, 256)));
}

uint32_t bam_from_mdeg(int64_t mdeg) {
  // 360 000 mdeg per turn; reduce first so the product cannot overflow.
  int64_t r = mdeg % 360000;
  if (r < 0) r += 360000;
  return static_cast<uint32_t>(static_cast<uint64_t>(div_round(r * 4294967296LL, 360000)));
}

}  // namespace dexmill
