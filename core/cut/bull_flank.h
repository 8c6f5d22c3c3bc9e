// The bull nose's flank on a ramp: where along the track a column's lowest
// point lies (w*, core/cut/sweep_piece.h's file comment), from the torus's
// geometry instead of a search of F(w) - m w. Internal to the sweep.
//
// Geometry. The bull nose is a flat disc of radius a swept by a ball of
// radius rc (a = R - rc). Its point that meets a column first along a
// move of slope m = tan(slope angle) is where its normal is perpendicular to
// the motion: with theta the normal's direction in the horizontal plane (from
// the track) and phi its angle from the vertical, tan(phi) cos(theta) = m.
// That point lies at radius rho = a + rc sin(phi) from the axis, at
// cross-track v = rho sin(theta) and along-track w* = rho cos(theta). With
// s = sin(phi) in [sin_b, 1] (sin_b = m / sqrt(1 + m^2): theta = 0, the
// ball's contact) and cos(theta) = m cot(phi), v = rho(s) sqrt(1 - m^2 (1 -
// s^2) / s^2) grows with s from 0 to R, and v^2 = v(s)^2 multiplied by
// s^2 / (R^2 (1 + m^2)) is the quartic, in lengths over R (alpha = a / R,
// gamma = rc / R, nu = v / R, beta2 = sin_b^2, kappa2 = 1 - beta2):
//   P(s) = gamma^2 s^4 + 2 alpha gamma s^3
//          + (alpha^2 - kappa2 nu^2 - beta2 gamma^2) s^2
//          - 2 beta2 alpha gamma s - beta2 alpha^2,
// negative below the root s* and positive above (P / s^2 = kappa2 (v(s)^2 -
// v^2) / R^2). Above s*, P is convex (P'' >= 2 (rho^2 / R^2 - kappa2 nu^2)
// > 0 there, as rho(s) >= rho(s*) >= v), so Newton's method started
// above s* descends to it without overshooting. The start: halving from s = 1
// while P stays >= 0 puts it within a factor 2 of s*, three bisections of
// that factor within 2^(1/8); from there Newton settles in about three
// steps over every tool shape, slope and offset.
//
// Why it may be approximate: w* is a minimum of the convex F(w) - m w, so an
// error dw in it changes the lowest height only by F'' dw^2 / 2, and the
// height itself is always evaluated exactly at the clamped w (the tool at a
// real position: never below the true envelope). The error bound of
// core/cut/sweep.h is checked against the double oracle in
// tests/test_sweep_bull.cpp.
//
// Outside 2^-16 <= |m| <= 2^4 (ramps gentler than 1 um in 65 mm or
// steeper than 86 degrees, where the fixed-point coefficients lose their
// precision) and when Newton has not settled in kBullNewtonSteps,
// bull_flank_w answers false and the caller searches as before.
//
// Ranges (q52: 1.0 = 2^52): alpha, gamma, beta2, kappa2, nu2 <= 1, so |c4|,
// |c3|, |c1|, |c0| <= 2^53 and |c2| <= 3 2^52; s in [sin_b, 1] <= 2^52;
// every product is 128-bit and shifted back by 52, so a term is below 2^55
// and P, P' (sums of four) below 2^57; Newton scales P by 2^up < 2^61 /
// |P|; 1 - s^2 <= 2^52, shifted by 28 only below 2^34 (< 2^62), else by 8;
// cos(theta)'s operands shifted to 62 bits; w* = (a + rc s) cos <= R.
#ifndef DEXMILL_CORE_CUT_BULL_FLANK_H
#define DEXMILL_CORE_CUT_BULL_FLANK_H

#include <stdint.h>

#include "core/cut/sweep_internal.h"
#include "core/math/fixed.h"

namespace dexmill {

constexpr int kBullNewtonSteps = 16;

// w* for the column at cross-track |v| = v_abs (U) of a piece with slope
// m_q30 (dz/ds, q30) and sin_q30 = m / sqrt(1 + m^2): *w_abs = |w*| in U (its
// sign is m's). The contact is on the tool, so w*^2 + v^2 <= R^2 but for
// the roundings (callers clamp r^2 to R^2). False: search instead.
inline bool bull_flank_w(const SweepTool& t, int64_t m_q30, int64_t sin_q30, int64_t v_abs, int64_t* w_abs) {
  // q52: a gentle ramp's root is near sin_b (2^-16 at the least) and its
  // coefficients near sin_b^2; q52 keeps 20 bits of them, and every value
  // below (|coefficients|, s <= 4) times s fits a 128-bit product.
  constexpr int kQ = 52;
  constexpr int64_t kOne = static_cast<int64_t>(1) << kQ;
  const int64_t m_abs = m_q30 < 0 ? -m_q30 : m_q30;
  if (m_abs < (static_cast<int64_t>(1) << 14) || m_abs > (static_cast<int64_t>(1) << 34) || t.r_u < 1) return false;
  if (v_abs >= t.r_u) {  // the rim: a chord of one point
    *w_abs = 0;
    return true;
  }
  const int64_t sin_abs = sin_q30 < 0 ? -sin_q30 : sin_q30;
  // nu in q30 (a column within 1/4 nm of its place: inside the backward bound).
  const int64_t nu_q30 = mul_shift_fit(v_abs, t.bull_inv_r_q62, 32);
  const int64_t nu2 = (nu_q30 * nu_q30) >> (60 - kQ);
  const int64_t beta2 = (sin_abs * sin_abs) >> (60 - kQ);
  const int64_t kappa2 = kOne - beta2;
  const int64_t c4 = t.bull_rc2_q52, c3 = t.bull_2arc_q52;
  const int64_t c2 = t.bull_a2_q52 - mul_shift_fit(kappa2, nu2, kQ) - mul_shift_fit(beta2, t.bull_rc2_q52, kQ);
  const int64_t c1 = -mul_shift_fit(beta2, t.bull_2arc_q52, kQ);
  const int64_t c0 = -mul_shift_fit(beta2, t.bull_a2_q52, kQ);
  // P and P' in two halves each (Estrin's scheme), which the CPU evaluates
  // side by side: the chain of dependent products is three long, not four.
  auto poly = [&](int64_t s, int64_t s2) {
    return mul_shift_fit(mul_shift_fit(c4, s2, kQ) + mul_shift_fit(c3, s, kQ) + c2, s2, kQ) +
           (mul_shift_fit(c1, s, kQ) + c0);
  };
  auto slope = [&](int64_t s, int64_t s2) {
    return mul_shift_fit(mul_shift_fit(4 * c4, s, kQ) + 3 * c3, s2, kQ) + (mul_shift_fit(2 * c2, s, kQ) + c1);
  };
  auto sq = [&](int64_t s) { return mul_shift_fit(s, s, kQ); };
  const int64_t s_lo = sin_abs << (kQ - 30);  // the root is at or above sin_b
  int64_t s = kOne;
  while ((s >> 1) > s_lo && poly(s >> 1, sq(s >> 1)) >= 0) s >>= 1;
  // Then within 2^(1/8) of s* by bisecting the factor (each a polynomial,
  // no division): Newton then needs about three steps instead of five.
  constexpr int64_t kRoot2Inv_q30[3] = {759250125, 902905651, 984625594};  // 2^(-1/2), 2^(-1/4), 2^(-1/8)
  for (const int64_t f : kRoot2Inv_q30) {
    const int64_t c = mul_shift_fit(s, f, 30);
    if (c > s_lo && poly(c, sq(c)) >= 0) s = c;
  }
  bool settled = false;
  int64_t last_step = INT64_MAX;
  for (int k = 0; k < kBullNewtonSteps && !settled; ++k) {
    const int64_t s2 = sq(s), d_p = slope(s, s2);
    if (d_p <= 0) return false;
    // P / P' in q52 with one 64-bit division: P 2^52 fits while P is
    // small (near the root); before that, P' gives up low bits instead (the
    // steps far from the root need no precision, only the last ones do).
    const int64_t p = poly(s, s2), p_abs = p < 0 ? -p : p;
    const int up = min_of(kQ, 61 - (64 - __builtin_clzll(static_cast<uint64_t>(p_abs) | 1)));
    const int64_t den = d_p >> (kQ - up);
    if (den <= 0) return false;
    const int64_t step = (p * (static_cast<int64_t>(1) << up)) / den;
    s = clamp(s - step, s_lo, kOne);
    // Settled when a shrinking step is 2^-9 of the scale the answer lives on
    // (s, or 1 - s near the rim and on steep ramps, where w* ~ sqrt(1 - s)):
    // Newton converges quadratically, so the error left after it is of the
    // order of its square, 2^-18 of the scale, and the height's error of
    // the square of w*'s (tests/test_sweep_bull.cpp measures it against a
    // double minimiser). Or at 2^-11 even where the steps stop
    // shrinking: there P's rounding over a small P' is all that is left.
    const int64_t step_abs = step < 0 ? -step : step, scale = min_of(s, kOne - s);
    settled = step_abs <= (scale >> 9) && (step_abs <= (scale >> 11) || step_abs < last_step);
    last_step = step_abs;
  }
  if (!settled) return false;
  // cos(theta) = m cot(phi) = m sqrt(1 - s^2) / s and rho = a + rc s. Near
  // s = 1 (steep ramps, the rim) 1 - s^2 is small: taken as e (2 - e), e =
  // 1 - s, and its root scaled up there, so that w* keeps its precision.
  const int64_t e = kOne - s;
  const int64_t x = mul_shift_fit(e, 2 * kOne - e, kQ);  // 1 - s^2, q52
  const int64_t sq_q40 = x < (static_cast<int64_t>(1) << 34)
                             ? static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(x) << 28))
                             : static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(x) << 8)) << 10;
  // m sqrt(1 - s^2) = s cos(theta) <= s, q40; then the quotient with both
  // operands shifted up to 62 bits: 31 good bits of cos(theta) in q30.
  const int64_t s_q40 = s >> (kQ - 40);
  if (s_q40 <= 0) return false;
  const int64_t num = min_of(mul_shift(m_abs, sq_q40, 30), s_q40);
  const int sh = __builtin_clzll(static_cast<uint64_t>(s_q40)) - 1;
  const int64_t cos_theta_q30 = min_of((num << sh) / ((s_q40 << sh) >> 30), static_cast<int64_t>(1) << 30);
  const int64_t rho_c_u = t.a_u + mul_shift_fit(t.rc_u, s, kQ);
  *w_abs = mul_shift_fit(rho_c_u, cos_theta_q30, 30);
  return true;
}

// w* (signed, U) for piece lp at cross-track |v| = v_abs, through the
// chain's memo when the piece has one; false as bull_flank_w (and nothing
// kept).
inline bool bull_flank_w_memo(const SweepTool& t, const SweepLine& lp, int64_t v_abs, int64_t* w) {
  BullFlankMemo* m = lp.bull_memo;
  const uint32_t key = static_cast<uint32_t>(v_abs + 1);
  BullFlankMemo::Slot* e = nullptr;
  if (m) {
    if (m->r_u != t.r_u || m->rc_u != t.rc_u) {
      const uint64_t inv = m->row_inv_q32;
      const uint8_t way = m->next_way;
      *m = BullFlankMemo{};
      m->r_u = t.r_u;
      m->rc_u = t.rc_u;
      m->row_inv_q32 = inv;
      m->next_way = way;
    }
    if (m->row_inv_q32) {  // the row's slot in the piece's way (core/cut/sweep_internal.h, BullFlankMemo)
      const uint64_t half_pitches = (static_cast<uint64_t>(v_abs) * m->row_inv_q32) >> 32;
      e = &m->slot[(2 * half_pitches + lp.bull_way) & ((1u << BullFlankMemo::kSlotBits) - 1)];
      // The other way holds the last piece's: the same slope (a chain's
      // pieces often repeat one) is a hit too.
      const BullFlankMemo::Slot* o = &m->slot[(2 * half_pitches + (lp.bull_way ^ 1)) & ((1u << BullFlankMemo::kSlotBits) - 1)];
      if (o->v_plus1 == key && o->m_q30 == lp.m_geo_q30 && o->sin_q30 == lp.ball_sin_q30) {
        *w = o->w_u;
        return true;
      }
    } else {
      const uint64_t h = (static_cast<uint64_t>(key) ^ static_cast<uint64_t>(lp.m_geo_q30) * 0x9E3779B97F4A7C15ull) *
                         0xC2B2AE3D27D4EB4Full;
      e = &m->slot[h >> (64 - BullFlankMemo::kSlotBits)];
    }
    if (e->v_plus1 == key && e->m_q30 == lp.m_geo_q30 && e->sin_q30 == lp.ball_sin_q30) {
      *w = e->w_u;
      return true;
    }
  }
  int64_t w_abs = 0;
  if (!bull_flank_w(t, lp.m_geo_q30, lp.ball_sin_q30, v_abs, &w_abs)) return false;
  *w = lp.m_geo_q30 < 0 ? -w_abs : w_abs;
  if (e) *e = BullFlankMemo::Slot{lp.m_geo_q30, lp.ball_sin_q30, key, static_cast<int32_t>(*w)};
  return true;
}

}  // namespace dexmill

#endif
