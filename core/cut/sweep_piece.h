// Swept envelope of a straight move (core/cut/sweep.h): the piece set-up
// and the row kernels, templates on the column loops' word width
// (core/config.h, kSweepWordBits). Private to the sweep: included only by
// core/cut/sweep_line.cpp, which instantiates the program's width, and
// core/cut/sweep_line_w.cpp, the other one (for the tests of both).
//
// Geometry. Let the move go from A to B, horizontal length l, unit direction
// e, and let a column P sit at along-track u and cross-track v from A. With
// the tool at along-track s in [0, l], the column meets the tool's lower
// surface at height z(s) + f(sqrt((u - s)^2 + v^2)), z(s) = zA + m*s. With
// w = u - s this is zA + m*u + [F(w) - m*w], F(w) = f(sqrt(w^2 + v^2)), which
// is convex in w for every cutter here (f convex and increasing in r). So the
// lowest point is at w = clamp(w*(v), u - l, u), where w*(v) minimises
// F(w) - m*w without the clamp, and it depends on v only:
//   flat:   m = 0: 0; else sign(m) * rho, rho = sqrt(R^2 - v^2) (the rim)
//   ball:   rho * m / sqrt(1 + m^2) (where the sphere's slope equals m)
//   V-bit:  m*|v| / sqrt(k^2 - m^2) while inside the cone, else the rim
//   bull:   the torus's contact, a quartic's root (core/cut/bull_flank.h)
// An error in w* changes the height only to second order (w* is a minimum),
// while the height itself is always evaluated exactly at the clamped w.
// The ball's flank has a closed form needing no second root: with
// w* = rho sin(phi), tan(phi) = m, F(w*) - m w* = R - rho (cos + m sin)
// = R - rho sqrt(1 + m^2), so a band column costs one square root (rho).
//
// Ranges (why the inner loops may use mul_shift_fit, which does not
// saturate): a piece is at most 2^29 U long and R <= 2^30 U, so |u|, |w| <
// 2^31 U and rho <= 2^30 U; a piece steeper than 2^24:1 is a plunge, so
// |slope| < 2^24 * 64 V/U / lsb <= 2^30 V/U and |u * slope| < 2^61 V; the
// ball's K = sqrt(1 + m^2) < 2^25, so rho * K < 2^55 U, and such a length
// times v_per_u_q32 (<= 2^38) shifted by 32 is below 2^61 V. Product by
// product, from core/cut/sweep.h's ranges (S(x) = x slope / 2^32):
//   setup_piece: dx_u, dy_u <= 2^29 + 4 (pieces of 2^27 nm + 1), l2 < 2^59,
//     len_q30 < 2^60; dz_u < 2^49, squared in 128 bits; m_geo_q30 < 2^54,
//     ball_k_q30 < 2^55; the V-bit's k20 < 2^27 (angles >= 1 degree), m20 <
//     k20 inside the cone, so k20^2 - m20^2 < 2^54, and c1 < 2^57.
//   w*: the ball's rho sin < 2^30, the rim rho, the bull's |w*| <= R
//     (bull_flank.h), the V-bit's |v| c1 < 2^58 tested against R before
//     it is squared; so w^2 + v2 <= 2 R^2 < 2^61 wherever a w is squared.
//   columns (flank_cost_v, side, the general direction): |u|, |u - w| <
//     2^31 (u in [-(4 R + 18), l + R + 1]), S < 2^61 V, a height za + S +
//     P < 2^55 + 2^61 + 2^42 < 2^62; ball_flank_v 2^61 V (above).
//   row set-up: a column's offset from the piece's origin (dx0_u, dy_row_u)
//     < 2^31 U (columns within R + 1 nm of the piece's box), times e (q30)
//     < 2^61, u and v accumulators (two such) < 2^62; u_min_q30 >= -(4 R +
//     18) 2^30 > -2^62.1, u_max_q30 < 2^61, the walk's row bounds (u e_y -
//     r e_x) > -2^62.4, NarrowRows' alpha - lo < 2^62.9; a step p_u e <=
//     2^62 (pitch <= 1 m: p_u <= 2^32).
//   along x: x_step <= p_u <= 2^32, x_dh_q16 saturated (mul_shift); the q16
//     run only on pieces whose tip stays within 2^42 V of z0 and whose
//     column step is below 2^60 (q16), so that |h_q16| < 2^59 and four
//     steps 2^62 (x_run_fits), else column by column from exact heights.
//   plunge: dx, dy < 2^30.1 U (R + 1 nm and a plunge's 2^-24 drift), r^2
//     < 2^61.2.
//   ball_floor_of, shaft_top_lsb, bull_row_floor_of: saturating products
//     (mul_shift), S(l) < 2^59, rc v_per_u < 2^36, sums below 2^62.
#ifndef DEXMILL_CORE_CUT_SWEEP_PIECE_H
#define DEXMILL_CORE_CUT_SWEEP_PIECE_H

#include <stdint.h>

#include <type_traits>

#include "core/cut/bull_flank.h"
#include "core/cut/stamp.h"
#include "core/cut/sweep_cut.h"
#include "core/cut/sweep_internal.h"
#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {
// Internal linkage, as in a .cpp of its own: each including file gets its
// copy, inlined as there (each uses every function; alone, as the header
// check compiles it, none is, which clang would report).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {

constexpr int64_t kQ30 = static_cast<int64_t>(1) << 30;
// Pieces of at most 2^27 nm keep every product below 2^63 (see sweep.h).
constexpr int64_t kMaxPieceNm = static_cast<int64_t>(1) << 27;


int64_t sign_of(int64_t v) { return v < 0 ? -1 : 1; }

// F(w) - m*w in V for the cross-track distance v (v2 = v^2), w^2 + v^2 <= R^2.
int64_t flank_cost_v(const SweepTool& t, const SweepLine& lp, int64_t w, int64_t v2) {
  return sweep_profile_v(t, w * w + v2) - mul_shift_fit(w, lp.slope_v_q32, 32);
}

// The ball's flank height F(w*) - m w* = R - rho sqrt(1 + m^2) in V (see
// the file comment); rho <= R, so it is within [R (1 - K), R], K the slope
// factor, and rounds like the profile (floor of rho, then of the product).
int64_t ball_flank_v(const SweepTool& t, const SweepLine& lp, int64_t rho) {
  return mul_shift_fit(t.r_u - mul_shift_fit(rho, lp.ball_k_q30, 30), t.v_per_u_q32, 32);
}

// rho(v) = floor(sqrt(R^2 - v^2)): the tool's half chord at cross-track v.
int64_t rho_of(const SweepTool& t, int64_t v2) {
  return static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(t.r2_u - v2)));
}

// w*(v): the unclamped minimiser of F(w) - m*w (see the file comment), given
// rho = rho_of(v2) (rows along x share it between pieces and neighbours).
inline int64_t best_w_rho(const SweepTool& t, const SweepLine& lp, int64_t v, int64_t v2, int64_t rho) {
  if (lp.level) return 0;
  if (t.kind == ToolKind::kBall) return mul_shift_fit(rho, lp.ball_sin_q30, 30);  // the common case first
  const int64_t rim = sign_of(lp.m_geo_q30) * rho;
  switch (t.kind) {
    case ToolKind::kFlat:
      return rim;
    case ToolKind::kBall:
      return mul_shift(rho, lp.ball_sin_q30, 30);
    case ToolKind::kVBit: {
      if (!lp.vbit_inside) return rim;
      // |v| <= 2^31 U, |c1| < 2^57 (m / sqrt(k^2 - m^2) with the root's
      // argument at least 1 in q20): w up to 2^58, far past the rim on a
      // ramp along the cone's slope; such a w is the rim's (w^2 > R^2), and
      // the test first keeps w^2 below 2^60 (unchecked, it overflowed for a
      // 30-degree V-bit 254 mm across).
      const int64_t w = mul_shift(v < 0 ? -v : v, lp.vbit_c1_q30, 30);
      return (w < 0 ? -w : w) <= t.r_u && w * w + v2 <= t.r2_u ? w : rim;
    }
    case ToolKind::kBullNose: {
      // From the torus's contact (core/cut/bull_flank.h); the search of the
      // convex F(w) - m w where that leaves it.
      int64_t w_flank = 0;
      if (bull_flank_w_memo(t, lp, v < 0 ? -v : v, &w_flank)) return w_flank;
      if (rho < 0) rho = rho_of(t, v2);
      int64_t lo = -rho, hi = rho;
      while (hi - lo > 2) {
        const int64_t third = (hi - lo) / 3;
        const int64_t m1 = lo + third, m2 = hi - third;
        if (flank_cost_v(t, lp, m1, v2) <= flank_cost_v(t, lp, m2, v2)) hi = m2; else lo = m1;
      }
      int64_t best = lo, best_cost = flank_cost_v(t, lp, lo, v2);
      for (int64_t w = lo + 1; w <= hi; ++w) {
        const int64_t c = flank_cost_v(t, lp, w, v2);
        if (c < best_cost) { best = w; best_cost = c; }
      }
      return best;
    }
  }
  return 0;
}

int64_t best_w(const SweepTool& t, const SweepLine& lp, int64_t v, int64_t v2) {
  if (lp.level) return 0;
  // The bull nose's w* needs no chord but where it searches (rho < 0: its own).
  return best_w_rho(t, lp, v, v2, t.kind == ToolKind::kBullNose ? -1 : rho_of(t, v2));
}

bool setup_piece(const SweepTool& t, int64_t za_v, int64_t zb_v, int64_t dx_u, int64_t dy_u, int64_t dz_nm,
                 SweepLine* lp) {
  lp->za_v = za_v;
  lp->zb_v = zb_v;
  lp->level = za_v == zb_v;
  const uint64_t l2 = static_cast<uint64_t>(dx_u * dx_u) + static_cast<uint64_t>(dy_u * dy_u);
  // The length with 30 fraction bits: the direction must be a unit vector
  // to 2^-30 even for a move a few U long (a 1 nm segment far from a column).
  // Along an axis (the common case) e is exactly (+-1, 0) or (0, +-1) and
  // the root is |d|: skip it.
  const bool axis = dx_u == 0 || dy_u == 0;
  const int64_t len_q30 = axis ? static_cast<int64_t>((abs_u64(dx_u) + abs_u64(dy_u)) << 30)
                               : static_cast<int64_t>(isqrt_u128(shl_u128(U128{0, l2}, 60)));
  lp->len_u = (len_q30 + (kQ30 >> 1)) >> 30;
  const int64_t dz_u = dz_nm * kSweepUnitsPerNm;
  // Steeper than 2^24:1 is cut as a plunge at the lower end: the horizontal
  // error is below |dz| / 2^24 (60 nm per metre of descent).
  lp->plunge = len_q30 == 0 || abs_u64(dz_u) >= (static_cast<uint64_t>(len_q30) >> 6);
  if (lp->plunge) return true;
  constexpr int64_t kQ60 = static_cast<int64_t>(1) << 60;
  lp->ex_q30 = axis ? (dx_u > 0 ? kQ30 : dx_u < 0 ? -kQ30 : 0) : muldiv_round(dx_u, kQ60, len_q30);
  lp->ey_q30 = axis ? (dy_u > 0 ? kQ30 : dy_u < 0 ? -kQ30 : 0) : muldiv_round(dy_u, kQ60, len_q30);
  // x * 2^s / l rounded: along an axis l is whole (len_q30 = len_u 2^30),
  // so the same quotient comes from 64-bit operands.
  auto per_len = [&](int64_t x, int s) {
    return axis ? muldiv_round(x, static_cast<int64_t>(1) << s, lp->len_u)
                : muldiv_round(x, static_cast<int64_t>(1) << (s + 30), len_q30);
  };
  lp->slope_v_q32 = per_len(zb_v - za_v, 32);
  lp->m_geo_q30 = per_len(dz_u, 30);
  lp->ball_k_q30 = kQ30;
  if (lp->level) return true;
  // sqrt(dz^2 + l^2) with a 128-bit sum; >= |dz| >= 1 (dz != 0 when not level).
  const U128 hyp2 = u128_add(sq_u128(dz_u), U128{0, l2});
  const int64_t hyp = static_cast<int64_t>(hyp2.hi ? isqrt_u128(hyp2) : isqrt_fast_u64(hyp2.lo));
  lp->ball_sin_q30 = muldiv_round(dz_u, kQ30, hyp);
  lp->ball_k_q30 = per_len(hyp, 30);  // <= 2^54: steeper is a plunge
  if (t.kind == ToolKind::kVBit) {
    // In q20 so that k^2 - m^2 stays in 64 bits (k <= cot(0.5 deg) < 2^7).
    const int64_t k20 = t.cot_q30 >> 10, m20 = lp->m_geo_q30 / 1024;
    lp->vbit_inside = (m20 < 0 ? -m20 : m20) < k20;
    if (lp->vbit_inside) {
      const int64_t den = static_cast<int64_t>(isqrt_u64(static_cast<uint64_t>(k20 * k20 - m20 * m20)));
      lp->vbit_inside = den > 0;
      if (den > 0) lp->vbit_c1_q30 = muldiv_round(m20, kQ30, den);
    }
  }
  return true;
}

// A floor under every height the ball's pieces compute for a column, so
// that a column whose top is already at or below it is left without its
// square root (most of a pocket's band: the laps before cut it lower).
// Heights computed for the column at (u, v) (v2 = min(v^2, R^2)) are
//   flank: za + S(u) + floor((R - floor(rho K)) g), rho = isqrt(R^2 - v2)
//   caps:  za + S(u - w) + floor((R - isqrt(R^2 - min(w^2 + v2, R^2))) g)
// with S(x) = floor(x m) (m = slope_v_q32 / 2^32, V per U) and g = V per U.
// The sphere lies above its paraboloid: R - sqrt(R^2 - r^2) >= r^2 / (2R)
// (r <= R, and R g >= r^2 g / (2R) up to reach2 for R >= 8 U). So
//   flank >= za + S(u) + v2 g / (2R) - R (K - 1) g - 1
//   caps  >= za + S(u) - m w + (w^2 + v2) g / (2R) - 2
//         >= za + S(u) + v2 g / (2R) - R m^2 / (2 g) - 2 (minimum over w),
// and both are >= S(u) + sweep_bowl_v(v2) + *floor_v with
// *floor_v = za - max(R (K - 1) g, R m^2 / (2 g)) - 3 - 3 (g + 1), each
// product rounded up; a saturated product only lowers the floor. The last
// term: a cap's r^2 is the grid frame's exact one (general_row), within
// 4R + 10 U^2 of w^2 + v2 from the walked u and v (each within 1 U), so its
// paraboloid term within 3 g of the one above (R >= 8 U). K < 1 (rounding) needs no
// term: then R (1 - K) >= (1 - K) v2 / (2R). False: no floor (not a ball, a
// plunge, or one too far down to matter).
bool ball_floor_of(const SweepTool& t, const SweepLine& lp, int64_t* floor_v) {
  if (t.kind != ToolKind::kBall || lp.plunge || t.r_u < 8) return false;
  auto up = [](int64_t x) { return x < INT64_MAX ? x + 1 : x; };  // rounds a floored product up
  const int64_t k_minus_1 = max_of(lp.ball_k_q30 - kQ30, int64_t{0});
  const int64_t drop_flank = up(mul_shift(up(mul_shift(t.r_u, k_minus_1, 30)), t.v_per_u_q32, 32));
  const int64_t m_abs = lp.slope_v_q32 < 0 ? -lp.slope_v_q32 : lp.slope_v_q32;
  const int64_t m_ratio_q30 = up(mul_shift(m_abs, t.u_per_v_q30, 32));  // m / g, dimensionless
  const int64_t m2_q30 = up(mul_shift(m_ratio_q30, m_ratio_q30, 30));
  const int64_t drop_caps = up(mul_shift(up(mul_shift(t.r_u, m2_q30, 31)), t.v_per_u_q32, 32));
  const int64_t drop = max_of(drop_flank, drop_caps);
  // 2^40 LSB down, beyond any top: no floor worth testing, and no overflow.
  if (drop > (static_cast<int64_t>(1) << 48)) return false;
  *floor_v = lp.za_v - drop - 3 - 3 * ((t.v_per_u_q32 >> 32) + 1);
  return true;
}

// The highest of p[0 .. n) (n >= 1): a max() per lane over blocks of a
// fixed count (-O2 vectorises them), the last block overlapping the one
// before (a max may see a top twice), and the lanes' max at the end.
template <class H>
inline H max_top(const H* p, int64_t n) {
  constexpr int kBlock = 16;
  H hi = 0;
  if (n < kBlock) {
    for (int64_t k = 0; k < n; ++k) hi = p[k] > hi ? p[k] : hi;
    return hi;
  }
  H lane[kBlock] = {};
  for (int64_t k = 0;; k += kBlock) {
    if (k > n - kBlock) k = n - kBlock;
    for (int e = 0; e < kBlock; ++e) lane[e] = p[k + e] > lane[e] ? p[k + e] : lane[e];
    if (k == n - kBlock) break;
  }
  for (int e = 0; e < kBlock; ++e) hi = lane[e] > hi ? lane[e] : hi;
  return hi;
}

// The bull nose's row floor: true when no column of a row along x (the
// `dv == 0` branch of sweep_piece, cross-track v, v2 = min(v^2, R^2)) can
// change, because every top of the row, in [row, row + n), is at or under
// the least height the piece computes on the row. Then the row needs no w*
// (a quartic's root), no profile and no side column. Only where a cut is a
// min() (shaft above every top): there a height h_v leaves the dexel as it
// is exactly when h_v >= sweep_keep_v(top), and the flank's q16 run exactly
// when h_q16 >= sweep_keep_v(top) 2^16.
//
// Proof. Let S(x) = floor(x sl / 2^32) (mul_shift_fit, sl = slope_v_q32, V
// per U in q32), P = sweep_profile_v, l = len_u, step = +-p the columns'
// step in u, and zlo = za + min(0, S(l)). P is nondecreasing in r^2 on
// [0, R^2] (isqrt is monotonic, d = min(r - a, rc) too, and so rc -
// isqrt(rc^2 - d^2) and its product with v_per_u_q32 > 0), and every r^2
// the row passes to it, min(w^2 + v2, R^2), is >= v2: each profile term is
// >= P(v2). And floor(x) - floor(y) >= floor(x - y).
//   start side (w = u): h = za + S(0) + P(..) >= za + P(v2) >= zlo + P(v2).
//   end side (w = u - l): h = za + S(l) + P(..) >= zlo + P(v2).
//   flank: column k of the run from u0 (u_k = u0 + k step, ws <= u_k <=
//     ws + l) gets h_q16 = (za - S(ws) + P(..) + S(u0)) 2^16 + k dh with
//     dh = floor(step sl / 2^16).
//     sl >= 0, step > 0: S(u0) >= S(ws) (u0 >= ws) and dh >= 0, so
//       h_q16 >= (za + P(v2)) 2^16 = (zlo + P(v2)) 2^16.
//     sl <= 0, step < 0: S(u0) - S(ws) >= floor((u0 - ws) sl / 2^32) >= S(l)
//       (0 <= u0 - ws <= l) and dh >= 0: h_q16 >= (zlo + P(v2)) 2^16.
//     sl step < 0 (the run falls, dh rounded down): S(u0) - S(ws) >
//       (u0 - ws) sl / 2^32 - 1 and k dh >= k step sl / 2^16 - k, so h_q16 >
//       (za + P(v2) - 1) 2^16 + (u_k - ws) sl / 2^16 - k, and (u_k - ws) sl
//       / 2^32 >= min(0, l sl / 2^32) >= min(0, S(l)): h_q16 > (zlo + P(v2)
//       - 1) 2^16 - k, an integer, so h_q16 >= (zlo + P(v2) - 1) 2^16 - (n -
//       2) for k <= n - 1.
// So floor_v = zlo + P(v2) - e, e = 0 but where the run falls, e = 1 +
// ceil((n - 2) / 2^16) there, has every height (the flank's h_q16 / 2^16)
// at or above it, and the row changes nothing when floor_v >=
// sweep_keep_v(top) for its highest top (sweep_keep_v is increasing). The
// wedge's and the cap's tests (which columns) do not matter: whichever are
// cut, each gets one of these heights. bull_row_floor_of computes the
// piece's part of floor_v, bull_row_above a row's test.
//
// The piece's part of the row floor (floor_v = zlo - e + P(v2)), once for
// its rows: zlo - e, P(R^2) = floor(rc g) (P's largest value: P is
// nondecreasing), and lim_hi: a top above it has sweep_keep_v(top) >
// zlo - e + P(R^2) (256 lim_hi > zlo - e + P(R^2) - 128) and keeps its row.
struct BullRowFloor {
  int64_t base_v, p_max, lim_hi;
};
BullRowFloor bull_row_floor_of(const SweepTool& t, const SweepLine& lp, int64_t n) {
  const int64_t zlo = lp.za_v + min_of(mul_shift_fit(lp.len_u, lp.slope_v_q32, 32), int64_t{0});
  const bool falls = lp.ex_q30 < 0 ? lp.slope_v_q32 > 0 : lp.slope_v_q32 < 0;
  const int64_t e = falls ? 1 + ((n + 65533) >> 16) : 0;
  BullRowFloor f;
  f.base_v = zlo - e;
  f.p_max = mul_shift_fit(t.rc_u, t.v_per_u_q32, 32);
  f.lim_hi = (f.base_v + f.p_max + (static_cast<int64_t>(1) << (kSweepVBits - 1))) >> kSweepVBits;
  return f;
}

template <class H>
bool bull_row_above(const SweepTool& t, const BullRowFloor& f, int64_t v2, const H* row, int64_t n) {
  // The row's ends first: on uncut stock the test ends there, without the scan.
  if (f.lim_hi < 0 || static_cast<int64_t>(row[0]) > f.lim_hi || static_cast<int64_t>(row[n - 1]) > f.lim_hi)
    return false;
  // floor_v >= sweep_keep_v(top) needs P(v2) >= need: without the profile
  // when need <= 0 (P >= 0), never when need exceeds P(R^2).
  const int64_t need = sweep_keep_v(max_top(row, n)) - f.base_v;
  if (need <= 0) return true;
  if (need > f.p_max) return false;
  return sweep_profile_v(t, v2) >= need;
}

// The rows of a bull-nose piece along x (sweep_piece's row loop, lo .. hi
// the columns of every row) that bull_row_above leaves, taken off both ends
// of rows = [first, last]: each row from either end while it changes
// nothing (or the loop would pass it by: |v| beyond R + 1). The rows taken
// off that the loop would have visited are counted here as it counts them
// (dexel_updates, the span log); a mirror pair may lose one row, whose
// mirror the loop then cuts alone, with the same heights. Outside the loop,
// not inlined, and the range returned by value: the row loop, every tool's,
// compiles as without it (paper-w3's ball: the same instruction count).
struct RowRange {
  int64_t first, last;
};
template <class H>
__attribute__((noinline)) RowRange bull_trim_rows(const DexelGrid<H>* g, const SweepTool& t, const SweepLine& lp,
                                                  int64_t oy_nm, int64_t lo, int64_t hi, CutStats* st, RowRange rows) {
  // Level pieces need no w* (w* = 0): their rows cost the loop about what
  // the test would.
  if (lp.level) return rows;
  const int64_t p = g->pitch_nm, n = hi - lo + 1, reach2 = sweep_reach2(t);
  const int64_t r_q30 = (t.r_u + 1) * kQ30;
  const BullRowFloor f = bull_row_floor_of(t, lp, n);
  auto leaves = [&](int64_t j) {
    const int64_t v_acc = (g->y0_nm + j * p - oy_nm) * kSweepUnitsPerNm * lp.ex_q30;  // as the loop's (e_y = 0)
    if (v_acc < -r_q30 || v_acc > r_q30) return true;  // passed by, not counted
    const int64_t v = (v_acc + kQ30 / 2) >> 30;
    if (v * v <= reach2 &&
        !bull_row_above(t, f, min_of(v * v, t.r2_u), g->top + g->index(0, static_cast<int32_t>(j)) + lo, n))
      return false;
    st->dexel_updates += static_cast<uint64_t>(n);
    if (st->log) st->log->add(static_cast<int32_t>(j), static_cast<int32_t>(lo), static_cast<int32_t>(hi));
    ++st->row_skips;
    return true;
  };
  while (rows.first <= rows.last && leaves(rows.first)) ++rows.first;
  while (rows.last > rows.first && leaves(rows.last)) --rows.last;
  return rows;
}

// floor(n / d) for n = n0, n0 + dn, n0 + 2 dn, ... (d > 0): two divisions
// to start, then an add and a compare a step (a Bresenham walk).
struct FloorWalk {
  int64_t q = 0, r = 0, dq = 0, dr = 0, d = 1;  // n = q d + r, 0 <= r < d; dn = dq d + dr
  void start(int64_t n0, int64_t dn, int64_t den) {
    d = den;
    q = div_floor(n0, d);
    r = n0 - q * d;
    dq = dn == 0 ? 0 : div_floor(dn, d);  // a walk that stays (along x) needs no division
    dr = dn - dq * d;
  }
  void next() {
    r += dr;
    const int64_t carry = r >= d ? 1 : 0;  // branch-free: rows alternate unpredictably
    r -= carry * d;
    q += dq + carry;
  }
};

// The columns i of a row with lo <= alpha + (i - i0) * beta <= hi, row after
// row as alpha grows by gamma: i0 + ceil(..) .. i0 + floor(..) with the
// quotients walked (per row, two divisions each would cost more than a
// short row's columns; more so where 64-bit division is a library call).
struct NarrowRows {
  // Initialised although start() sets every field before use: GCC -O3
  // cannot see that a walk is only applied after its start.
  bool flat = true;              // beta == 0: the whole row or none
  int64_t alpha = 0, gamma = 0;  // flat: the row's alpha and its step
  int64_t lo = 0, hi = -1;       // flat: the bounds
  FloorWalk first, last;         // otherwise: i0 - first.q .. i0 + last.q
  void start(int64_t alpha0, int64_t gamma_, int64_t beta, int64_t lo_, int64_t hi_) {
    flat = beta == 0;
    alpha = alpha0;
    gamma = gamma_;
    lo = lo_;
    hi = hi_;
    if (flat) return;
    // ceil(x / b) = -floor(-x / b); for beta < 0 both sides flip sign.
    if (beta > 0) {
      first.start(alpha0 - lo_, gamma_, beta);
      last.start(hi_ - alpha0, -gamma_, beta);
    } else {
      first.start(hi_ - alpha0, -gamma_, -beta);
      last.start(alpha0 - lo_, gamma_, -beta);
    }
  }
  // Narrows [*i_lo, *i_hi] to the current row's columns.
  void apply(int64_t i0, int64_t* i_lo, int64_t* i_hi) const {
    if (flat) {
      if (alpha < lo || alpha > hi) *i_hi = *i_lo - 1;
      return;
    }
    *i_lo = max_of(*i_lo, i0 - first.q);
    *i_hi = min_of(*i_hi, i0 + last.q);
  }
  void next() {
    if (flat) {
      alpha += gamma;
    } else {
      first.next();
      last.next();
    }
  }
};

// The flank's inner loop (figure 2 reduced to a min()): top = min(top,
// (h >> 24)) with h stepping by dh, q16 V with the rounding added. True when
// a top changed. Branch-free, the changed flag folded from old ^ new.
template <class H>
inline uint32_t min_at(H* p, int64_t h) {
  const H old = *p;
  const int64_t cb = h >> (16 + kSweepVBits);
  const H nv = cb < static_cast<int64_t>(old) ? static_cast<H>(cb) : old;
  *p = nv;
  return static_cast<uint32_t>(old ^ nv);
}

template <class H>
bool min_run(H* p, H* const end, int64_t h, int64_t dh) {
  uint32_t diff = 0;
  // Four columns a step: the loop's own bookkeeping is a third of a column.
  // (|dh| <= 2^60: the caller's range, core/cut/sweep.h.)
  for (const int64_t dh4 = 4 * dh; end - p >= 4; p += 4, h += dh4)
    diff |= min_at(p, h) | min_at(p + 1, h + dh) | min_at(p + 2, h + 2 * dh) | min_at(p + 3, h + 3 * dh);
  for (; p != end; ++p, h += dh) diff |= min_at(p, h);
  return diff != 0;
}

// min_run on a row and its mirror, which take the same heights: one DDA
// for both. Bit 0 of the result: p changed; bit 1: q changed.
template <class H>
unsigned min_run_pair(H* p, H* q, int64_t n, int64_t h, int64_t dh) {
  uint32_t dp = 0, dq = 0;
  for (int64_t k = 0; k < n; ++k, h += dh) {
    dp |= min_at(p + k, h);
    dq |= min_at(q + k, h);
  }
  return (dp != 0 ? 1u : 0u) | (dq != 0 ? 2u : 0u);
}

// min_run of a level run (dh = 0): min() of one height c, a loop compilers
// vectorise (level moves are most of pocketing, facing and air moves).
template <class H>
inline H min_level_at(H* p, H c) {
  const H old = *p, nv = old < c ? old : c;
  *p = nv;
  return static_cast<H>(old ^ nv);
}

template <class H>
bool min_level(H* p, H* const end, H c) {
  H diff = 0;
  // Blocks of a fixed count: -O2's cost model vectorises only those.
  constexpr int kBlock = 16;
  for (; end - p >= kBlock; p += kBlock)
    for (int k = 0; k < kBlock; ++k) diff = static_cast<H>(diff | min_level_at(p + k, c));
  for (; p != end; ++p) diff = static_cast<H>(diff | min_level_at(p, c));
  return diff != 0;
}

// min_level on a row and its mirror (distinct rows: restrict lets -O2
// vectorise both in one loop). Bits as min_run_pair's result.
template <class H>
unsigned min_level_pair(H* __restrict p, H* __restrict q, int64_t n, H c) {
  H dp = 0, dq = 0;
  constexpr int kBlock = 16;
  int64_t k = 0;
  for (; n - k >= kBlock; k += kBlock)
    for (int e = 0; e < kBlock; ++e) {
      dp = static_cast<H>(dp | min_level_at(p + k + e, c));
      dq = static_cast<H>(dq | min_level_at(q + k + e, c));
    }
  for (; k < n; ++k) {
    dp = static_cast<H>(dp | min_level_at(p + k, c));
    dq = static_cast<H>(dq | min_level_at(q + k, c));
  }
  return (dp != 0 ? 1u : 0u) | (dq != 0 ? 2u : 0u);
}

// Which columns behind the start (lowest point: the tool standing at a) a
// piece cuts: all, none, or the chain's wedge (core/cut/sweep.h, SweepChain).
enum class StartCap : uint8_t { kCut, kSkip, kWedge };

struct PieceCaps {
  StartCap start;
  const SweepLine* prev;  // kWedge: the piece before, which ended at a
  bool end;               // cut the columns whose lowest point is the tool at b
  RootMemo* roots;        // the chain's roots, or null
};

// rho(v) through the memo (core/cut/sweep_internal.h, RootMemo) when there is one.
int64_t rho_memo(const SweepTool& t, int64_t v2, RootMemo* m) {
  if (!m) return rho_of(t, v2);
  const uint64_t x = static_cast<uint64_t>(t.r2_u - v2);
  const unsigned slot = static_cast<unsigned>((x * 0x9E3779B97F4A7C15ull) >> (64 - RootMemo::kSlotBits));
  if (m->key[slot] != x) {
    m->key[slot] = x;
    m->root[slot] = static_cast<uint32_t>(rho_of(t, v2));
  }
  return m->root[slot];
}

// The range [lo, hi] of w*(v) over every v (the file comment), signed: 0
// when level; the ball's w* = floor(rho sin) is monotonic in rho in [0, R],
// so it lies between 0 and w_r = floor(R sin) (behind the start on a
// descent, ahead of it on an ascent); other shapes may reach the rim.
// Outside it a column's side (behind the start, past the end) is decided
// without the root that w* needs.
struct WRange {
  int64_t lo, hi;
};
WRange w_range_of(const SweepTool& t, const SweepLine& lp) {
  if (lp.plunge || lp.level) return WRange{0, 0};
  if (t.kind != ToolKind::kBall) return WRange{-t.r_u, t.r_u};
  const int64_t w_r = mul_shift_fit(t.r_u, lp.ball_sin_q30, 30);
  return WRange{min_of(w_r, int64_t{0}), max_of(w_r, int64_t{0})};
}

// u >= w*(v) for piece lp (u, v in its frame, from its end): the piece's
// lowest point for the column is at that end. Outside w_range_of no root.
bool at_or_past_w(const SweepTool& t, const SweepLine& lp, int64_t u, int64_t v) {
  const WRange wr = w_range_of(t, lp);
  if (u >= wr.hi) return true;
  if (u < wr.lo) return false;
  return u >= best_w(t, lp, v, min_of(v * v, t.r2_u));
}

// True when the previous piece, which ended at the joint, has its lowest
// point for the column at (dx, dy) U from the joint at that end.
bool prev_ends_here(const SweepTool& t, const SweepLine& prev, int64_t dx, int64_t dy) {
  const int64_t u = (dx * prev.ex_q30 + dy * prev.ey_q30 + kQ30 / 2) >> 30;  // from the joint
  const int64_t v = (dy * prev.ex_q30 - dx * prev.ey_q30 + kQ30 / 2) >> 30;
  return at_or_past_w(t, prev, u, v);
}

// The least along-track u (U, from a) of a column the piece may cut: behind
// it the lowest point is the tool at a, and with kWedge only columns the
// previous piece also reaches at its end count. That needs u_p >= lo_p
// (w_range_of) in the previous frame, u_p = u cos + v' sin with |v'| <= R
// (turns up to 60 degrees; beyond, the whole cap is a candidate).
int64_t u_min_of(const SweepTool& t, const SweepLine& lp, const PieceCaps& caps, int64_t w_lo) {
  const int64_t whole = -t.r_u - 1;
  if (caps.start == StartCap::kCut) return whole;
  if (caps.start == StartCap::kSkip) return w_lo - 1;
  const SweepLine& p = *caps.prev;
  const int64_t wbp = -w_range_of(t, p).lo + 2;  // >= -lo_p, >= 2
  // Straight on (a polyline along one line: raster passes): cos = 1,
  // sin = 0, what the general case below computes, without its products.
  if (lp.ex_q30 == p.ex_q30 && lp.ey_q30 == p.ey_q30 && (lp.ex_q30 == 0 || lp.ey_q30 == 0))
    return min_of(w_lo - 1, -(wbp + 2) - 2);
  const int64_t c = mul_shift(lp.ex_q30, p.ex_q30, 30) + mul_shift(lp.ey_q30, p.ey_q30, 30);
  const int64_t sn = mul_shift(lp.ex_q30, p.ey_q30, 30) - mul_shift(lp.ey_q30, p.ex_q30, 30);
  if (c < kQ30 / 2) return whole;
  const int64_t reach = wbp + mul_shift(t.r_u + 2, sn < 0 ? -sn : sn, 30) + 2;
  return min_of(w_lo - 1, -div_ceil(reach * kQ30, c) - 2);
}

// floor(x * slope / 2^32), mul_shift_fit's bits: with x and the slope
// within int32 the exact product is one 32 x 32 -> 64-bit multiply (forced
// inline: a column's height takes one or two). The int32_t form only where
// the slope fits int32 (PieceRows::narrow_fits).
struct SlopeMul {
  int64_t slope;
  int32_t slope32;
  explicit SlopeMul(int64_t s) : slope(s), slope32(static_cast<int32_t>(s)) {}
  __attribute__((always_inline)) int64_t operator()(int32_t x) const {
    return (static_cast<int64_t>(x) * slope32) >> 32;
  }
  __attribute__((always_inline)) int64_t operator()(int64_t x) const { return mul_shift_fit(x, slope, 32); }
};

// What a piece left for its chain: the tool at its end cut as a min()
// (covered), pending, or cut with a shaft below some top (open: the next
// move's start cap reaches higher and is cut again).
enum class PieceEnd : uint8_t { kCovered, kPending, kOpen };

// The flank's q16 run (along_x_flank) holds heights within 2^43 V of z0
// (piece_rows, x_run_fits).
constexpr int64_t kRunMaxV = static_cast<int64_t>(1) << 43;

// The column helpers the row kernels call (PieceCut::cut, shaft_top_lsb):
// inlined where speed is asked for (-O2, -O3: GCC otherwise calls them once
// a column), the compiler's choice at -Os (it keeps cut out of line:
// inlined, it crowds the column loops' registers on a Cortex-M, +3.5 % on
// make panel's cut). PieceRows::start_ok is inlined at every level (out of
// line at -Os it cost 0.5 % of the panel's cut).
#ifdef __OPTIMIZE_SIZE__
#define DEXMILL_SWEEP_COLUMN_INLINE inline
#else
#define DEXMILL_SWEEP_COLUMN_INLINE __attribute__((always_inline)) inline
#endif

// How a piece cuts a column (figure 2, sweep_cut_dexel): the grid, the
// piece, its shaft tops. A copy of it is what goes out of line
// (flank_exact), so that nothing of the piece's set-up (PieceRows) has its
// address taken and the column loops keep it in registers.
template <class H>
struct PieceCut {
  DexelGrid<H>* g;
  const SweepTool* t;
  const SweepLine* lp;
  int64_t ct_lsb, ct_plunge_lsb;
  bool shaft_above;  // the shaft top is above every top: a cut is figure 2's cases a, b, e

  // Figure 2's ct at a column (along-track u, v2 = min(v^2, R^2)), needed
  // only when the shaft is below some top: the union of the tool's column
  // intervals over the positions covering the column is [lowest point,
  // shaft top of the highest such position]. A level piece has one shaft
  // top, a plunge its upper end's; on a ramp the column is covered for s in
  // [u - rho, u + rho] (within [0, l]) and z is monotonic in s. Rounded
  // down like ct_lsb (never more than the exact top: a shallower cut).
  DEXMILL_SWEEP_COLUMN_INLINE int64_t shaft_top_lsb(int64_t u, int64_t v2) const {
    if (lp->level) return ct_lsb;
    if (lp->plunge) return ct_plunge_lsb;
    const int64_t rho = rho_of(*t, v2);
    const int64_t s = clamp(lp->zb_v > lp->za_v ? u + rho : u - rho, int64_t{0}, lp->len_u);
    return (lp->za_v + mul_shift_fit(s, lp->slope_v_q32, 32) + t->len_v) >> kSweepVBits;
  }
  // Cuts dexel i of the row at wt, wb with the lowest height h_v.
  DEXMILL_SWEEP_COLUMN_INLINE bool cut(H* wt, H* wb, int64_t i, int64_t h_v, int64_t u, int64_t v2) const {
    return sweep_cut_dexel<H>(g, &wt[i], &wb[i], h_v, shaft_above ? ct_lsb : shaft_top_lsb(u, v2), shaft_above);
  }
};

// The flank of an x-parallel row (and of its mirror mt, mb, when not null)
// column by column from exact heights, for pieces whose q16 run could
// overflow (piece_rows, x_run_fits): |flank_v| < 2^55 + 2^61, S(u) < 2^61,
// their sum a height the tool reaches (< 2^56), clamped to +-lim_v (2^43 V):
// a height past either bound cuts as any other past it (above every top,
// below every bottom), so the bits are the exact height's. Out of line: the
// rows' usual loop compiles as without it. Bit 0: the row changed; bit 1:
// the mirror.
template <class H>
__attribute__((noinline)) unsigned flank_exact(const PieceCut<H> c, H* wt, H* wb, H* mt, H* mb, int64_t v2,
                                               int64_t f_lo, int64_t f_hi, int64_t u0, int64_t step,
                                               int64_t flank_v, int64_t lim_v) {
  bool row = false, mirror = false;
  for (int64_t i = f_lo, u = u0; i <= f_hi; ++i, u += step) {
    const int64_t h_v = clamp(flank_v + mul_shift_fit(u, c.lp->slope_v_q32, 32), -lim_v, lim_v);
    row |= c.cut(wt, wb, i, h_v, u, v2);
    if (mt) mirror |= c.cut(mt, mb, i, h_v, u, v2);
  }
  return (row ? 1u : 0u) | (mirror ? 2u : 0u);
}

// A piece set up for its rows (piece_frame, piece_rows): what the row
// kernels read. Kernels run inside sweep_piece (forced inline: the column
// loops compile as one function's, with the lambdas in them inlined).
template <class H>
struct PieceRows : PieceCut<H> {
  const SweepTuning* tune;
  PieceCaps caps;
  PointNm o;  // the frame's origin: a, or a plunge's lower end
  int64_t zlow_v, hmax;
  int64_t p, p_u, reach2, r_q30;
  int64_t i_first, i_last, j_first, j_last;
  int64_t dx0_u;  // column i_first - origin, U
  int64_t end_dx_u, end_dy_u;  // the end b - origin, U (the end cap's centre)
  WRange wr;
  int64_t u_min_q30, u_max_q30;  // the along-track range of columns the caps leave (u_min_of)
  bool collinear, along_x, walk;
  // Along x, u(i) = x_u_lo + (i - x_lo) * x_step exactly (e = (+-1, 0)) on
  // every row, and a flank's heights step by x_dh_q16 a column.
  int64_t x_lo, x_hi, x_step, x_u_lo, x_dh_q16;
  bool x_run_fits, mirrored;
  int64_t mirror_sum;
  bool cull;  // the ball's floor (ball_floor_of) in a general direction
  int64_t ball_floor_v;
  bool ball, vbit_cone;  // vbit_cone: a V-bit ramp inside its cone (setup_piece)
  // The general direction's columns fit 32-bit words (general_row): tools up
  // to R = 2^28 U (67 mm): NarrowRows keeps |v_acc| <= (R + 1) 2^30 and u_acc
  // in [u_min, u_max] 2^30 with u_min >= -(4R + 14) (u_min_of: reach <= 2R +
  // 6 over c >= 1/2) and u_max <= l + R + 1 <= 2^29 + 2^28 + 1; |w*| <= R
  // (w*^2 + v^2 <= R^2, or the rim), so |u|, |v|, |w|, |u - l| and |u - w*|
  // stay below 2^30 + 2^28 + 14 < 2^31. The slope products take the 32 x
  // 32-bit form only with a slope within int32 (V per U q32 below 1/2: not
  // the steepest ramps on the finest LSBs).
  bool narrow_fits;

  // Start-side column at (u, v), i: cut it? (kWedge: the previous piece's
  // lowest point is at this joint too.)
  __attribute__((always_inline)) inline bool start_ok(int64_t u, int64_t v, int64_t i, int64_t dy_row_u) const {
    if (caps.start != StartCap::kWedge) return caps.start == StartCap::kCut;
    if (collinear) return at_or_past_w(*this->t, *caps.prev, u, v);
    return prev_ends_here(*this->t, *caps.prev, dx0_u + (i - i_first) * p_u, dy_row_u);
  }
};

// A row kernel's row: columns lo .. hi of row j (tops wt, bottoms wb) at
// cross offset dy_row_u from the origin, their offsets u_acc, v_acc (q30)
// at lo; along x its mirror jm too, when pair. Scalars, not a struct:
// where a compiler keeps structs in memory (-Os), a row would write and
// read it back.
template <class H, int W>
PieceEnd sweep_piece(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, PointNm a, PointNm b, CutStats* st,
                     PieceCaps caps, SweepLine* lp_out);

// The tool standing at p, whole.
template <class H, int W>
void cut_tool_at(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, PointNm p, CutStats* st) {
  SweepLine unused;
  sweep_piece<H, W>(g, t, tune, p, p, st, PieceCaps{StartCap::kCut, nullptr, true, nullptr}, &unused);
}

// The piece's frame (setup_piece) and its box of columns: false when it
// cuts nothing, with *result what it leaves for its chain.
template <class H, int W>
__attribute__((always_inline)) inline bool piece_frame(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune,
                                                      PointNm a, PointNm b, CutStats* st, PieceCaps caps,
                                                      SweepLine* lp_out, PieceRows<H>* s, PieceEnd* result) {
  *result = PieceEnd::kCovered;
  const int64_t za_v = sweep_height_v(*g, a.z_nm), zb_v = sweep_height_v(*g, b.z_nm);
  s->zlow_v = min_of(za_v, zb_v);
  s->hmax = height_max<H>();
  // Entirely above every top, or the whole tool (shaft top at the higher
  // end) below the grid's floor: nothing to cut, here or at either end.
  if (s->zlow_v >= (s->hmax << kSweepVBits) || max_of(za_v, zb_v) + t.len_v <= 0) return false;
  // The shaft top of the piece's lowest position bounds every column's:
  // when even that is above every top, figure 2 reduces to cases a, b, e.
  s->ct_lsb = (s->zlow_v + t.len_v) >> kSweepVBits;
  s->shaft_above = s->ct_lsb >= g->top_bound_lsb;
  // Only a min() per column may leave out dominated heights (SweepChain):
  // otherwise cut the previous end cap now, with its own shaft, and this
  // piece's caps in full.
  if (!s->shaft_above) {
    if (caps.start == StartCap::kWedge) cut_tool_at<H, W>(g, t, tune, a, st);
    if (caps.start != StartCap::kSkip) caps.start = StartCap::kCut;
    caps.end = true;
  }
  SweepLine& lp = *lp_out;
  const int64_t dx_u = (b.x_nm - a.x_nm) * kSweepUnitsPerNm, dy_u = (b.y_nm - a.y_nm) * kSweepUnitsPerNm;
  setup_piece(t, za_v, zb_v, dx_u, dy_u, b.z_nm - a.z_nm, &lp);
  // A plunge is the tool at its lower end (the shaft covers the rest).
  s->o = a;
  if (lp.plunge && zb_v < za_v) s->o = b;
  s->end_dx_u = (b.x_nm - s->o.x_nm) * kSweepUnitsPerNm;
  s->end_dy_u = (b.y_nm - s->o.y_nm) * kSweepUnitsPerNm;
  s->ct_plunge_lsb = (max_of(za_v, zb_v) + t.len_v) >> kSweepVBits;
  SweepColumns box;
  if (!sweep_columns(*g, t, min_of(a.x_nm, b.x_nm), max_of(a.x_nm, b.x_nm), min_of(a.y_nm, b.y_nm),
                     max_of(a.y_nm, b.y_nm), &box))
    return false;
  s->g = g;
  s->t = &t;
  s->tune = &tune;
  s->lp = &lp;
  s->caps = caps;
  s->p = g->pitch_nm;
  s->i_first = box.i_first;
  s->i_last = box.i_last;
  s->j_first = box.j_first;
  s->j_last = box.j_last;
  st->instances++;
  *result = !s->shaft_above ? PieceEnd::kOpen : lp.plunge || caps.end ? PieceEnd::kCovered : PieceEnd::kPending;
  s->p_u = s->p * kSweepUnitsPerNm;
  s->reach2 = sweep_reach2(t);
  s->dx0_u = (g->x0_nm + s->i_first * s->p - s->o.x_nm) * kSweepUnitsPerNm;
  s->r_q30 = (t.r_u + 1) * kQ30;
  s->wr = w_range_of(t, lp);
  s->u_min_q30 = lp.plunge ? 0 : u_min_of(t, lp, caps, s->wr.lo) * kQ30;
  s->u_max_q30 = (lp.len_u + (caps.end ? t.r_u : s->wr.hi) + 1) * kQ30;
  s->collinear = caps.start == StartCap::kWedge && caps.prev->ex_q30 == lp.ex_q30 && caps.prev->ey_q30 == lp.ey_q30;
  s->ball = t.kind == ToolKind::kBall;
  // (setup_piece sets vbit_inside only for ramps: test it only there.)
  s->vbit_cone = t.kind == ToolKind::kVBit && !lp.plunge && !lp.level && lp.vbit_inside;
  s->narrow_fits = t.r_u <= (static_cast<int64_t>(1) << 28) && detail::fits_i32(lp.slope_v_q32);
  return true;
}

// The piece's rows and, along x, their common columns: the columns within
// reach across (|v| <= R) and along the track, row after row (u and v grow
// by p e_y and p e_x from one row to the next). Along x the along-track
// range is the same on every row (e_y = 0): it is taken once, and rows test
// their v alone.
template <class H>
__attribute__((always_inline)) inline void piece_rows(PieceRows<H>* s, NarrowRows* across, NarrowRows* along,
                                                      CutStats* st) {
  DexelGrid<H>* const g = s->g;
  const SweepTool& t = *s->t;
  const SweepLine& lp = *s->lp;
  const int64_t p = s->p, p_u = s->p_u;
  s->along_x = !lp.plunge && lp.ey_q30 == 0;
  s->walk = !lp.plunge && !s->along_x;
  if (s->walk) {
    // The rows of the box that meet the piece's rectangle of columns (u in
    // [u_min, u_max], |v| <= R + 1): a move at an angle crosses fewer rows
    // than its box holds (one along y, 5 rows, in a box 63 rows tall for a
    // 3 mm ball on a 0.1 mm grid), and the walk below spends a row's set-up
    // on each. dy = u e_y + v e_x, widened for |e| = 1 +- 2^-29 and the
    // rounding; the rows left out are those NarrowRows would find empty.
    // (u_min_q30 and u_max_q30 are whole U: exact shifts.)
    const int64_t u_lo = s->u_min_q30 >> 30, u_hi = s->u_max_q30 >> 30, r_v = t.r_u + 1;
    const int64_t ey = lp.ey_q30, ex_abs = lp.ex_q30 < 0 ? -lp.ex_q30 : lp.ex_q30;
    const int64_t lo_q30 = min_of(u_lo * ey, u_hi * ey) - r_v * ex_abs;
    const int64_t hi_q30 = max_of(u_lo * ey, u_hi * ey) + r_v * ex_abs;
    const int64_t y_lo_u = (lo_q30 >> 30) - ((lo_q30 < 0 ? -lo_q30 : lo_q30) >> 56) - 4;
    const int64_t y_hi_u = -((-hi_q30) >> 30) + ((hi_q30 < 0 ? -hi_q30 : hi_q30) >> 56) + 4;
    const int64_t oy_u = (s->o.y_nm - g->y0_nm) * kSweepUnitsPerNm;
    s->j_first = max_of(s->j_first, div_ceil(oy_u + y_lo_u, p_u));
    s->j_last = min_of(s->j_last, div_floor(oy_u + y_hi_u, p_u));
  }
  if (!lp.plunge) {
    const int64_t dy0_u = (g->y0_nm + s->j_first * p - s->o.y_nm) * kSweepUnitsPerNm;
    along->start(s->dx0_u * lp.ex_q30 + dy0_u * lp.ey_q30, p_u * lp.ey_q30, p_u * lp.ex_q30, s->u_min_q30,
                   s->u_max_q30);
    if (s->walk)
      across->start(dy0_u * lp.ex_q30 - s->dx0_u * lp.ey_q30, p_u * lp.ex_q30, -p_u * lp.ey_q30, -s->r_q30,
                      s->r_q30);
  }
  s->x_lo = s->i_first;
  s->x_hi = s->i_last;
  if (s->along_x) along->apply(s->i_first, &s->x_lo, &s->x_hi);
  s->x_step = s->along_x ? p_u * lp.ex_q30 / kQ30 : 0;
  s->x_u_lo = s->along_x ? (s->dx0_u + (s->x_lo - s->i_first) * p_u) * lp.ex_q30 / kQ30 : 0;
  // |x_step| <= p_u <= 2^32 and |slope| < 2^62: saturated (a metre's pitch
  // on a steep ramp), and then not used (below).
  s->x_dh_q16 = s->along_x ? mul_shift(s->x_step, lp.slope_v_q32, 16) : 0;
  // The flank's q16 DDA (the x-parallel rows below) wants |h| < 2^43 V, so
  // that |h_q16| < 2^59, and a step |dh_q16| < 2^60, four of them 2^62.
  // A flank height is that of a point of the tool over the piece, within
  // [min(za, zb), max(za, zb) + P(R^2)] to 2^8 V, P(R^2) < 2^42 V (the
  // stick-out's 10 m): so |za|, |zb| < 2^42 V keeps it, and a run of two
  // columns or more then steps by less than 2^44 V; a larger step (a metre's
  // pitch) means runs of one column. Otherwise (a tip 2^34 LSB off the
  // grid's z0, on LSBs of a few nm) the flank is cut column by column.
  const int64_t half = kRunMaxV >> 1, za_v = lp.za_v, zb_v = lp.zb_v;
  s->x_run_fits = za_v > -half && za_v < half && zb_v > -half && zb_v < half && s->x_dh_q16 > -(kRunMaxV << 17) &&
                  s->x_dh_q16 < (kRunMaxV << 17);
  // Along x with the move on a row or half way between two (a raster pass
  // whose stepover the pitch divides), rows j and mirror_sum - j sit at
  // cross offsets v and -v, where every height is the same: set each such
  // pair up once and cut both. Not for a turning wedge, whose start side is
  // tested in the previous piece's frame, where the two differ.
  s->mirrored = s->along_x && (s->caps.start != StartCap::kWedge || s->collinear) &&
                (2 * (s->o.y_nm - g->y0_nm)) % p == 0;
  s->mirror_sum = s->mirrored ? 2 * (s->o.y_nm - g->y0_nm) / p : -1;
  // Rows in a general direction skip columns under the ball's floor. Only
  // where a cut is a min() (with the shaft below some top, a cut column's
  // interval reaches up to its shaft top).
  s->ball_floor_v = 0;
  s->cull = s->walk && s->shaft_above && s->tune->skip_under_floor && ball_floor_of(t, lp, &s->ball_floor_v);
  // Bull-nose rows along x under their floor (bull_row_above), from both
  // ends of the piece's rows, are left whole.
  if (s->along_x && s->shaft_above && t.kind == ToolKind::kBullNose && s->tune->bull_row_floor && s->x_lo <= s->x_hi) {
    const RowRange rows =
        bull_trim_rows(g, t, lp, s->o.y_nm, s->x_lo, s->x_hi, st, RowRange{s->j_first, s->j_last});
    s->j_first = rows.first;
    s->j_last = rows.last;
  }
}

// The row kernels: the columns lo .. hi of one row of a piece (a plunge's,
// one along x, one in a general direction), each a template on the word
// width W of its column loop (core/config.h, kSweepWordBits), with the same
// bits for both. True when a top of the row changed.
//
// A plunge's row: the tool standing at o, r^2 = dx^2 + dy^2, dx stepping by
// the pitch. I (dx's type) is int32_t in 32-bit words when dx is within it
// at both ends of the row (so everywhere between), for one-multiply
// squares; dx is walked unsigned, so that the step past the last column may
// wrap unread.
template <class H, int W>
__attribute__((always_inline)) inline bool plunge_row(const PieceRows<H>& s, int64_t lo, int64_t hi, int64_t dy_row_u,
                                                     H* const wt, H* const wb) {
  const SweepTool& t = *s.t;
  const bool flat = t.kind == ToolKind::kFlat;  // a profile of 0
  DexelGrid<H>* const g = s.g;
  const bool shaft_above = s.shaft_above;
  const int64_t reach2 = s.reach2, zlow_v = s.zlow_v, ct_lsb = s.ct_lsb;
  const int64_t dy2 = dy_row_u * dy_row_u;
  const int64_t dx_lo = s.dx0_u + (lo - s.i_first) * s.p_u, dx_hi = dx_lo + (hi - lo) * s.p_u;
  auto columns = [&](auto dx_first) {
    using I = decltype(dx_first);
    using UI = typename std::make_unsigned<I>::type;
    UI dx = static_cast<UI>(dx_first);
    const UI step = static_cast<UI>(s.p_u);
    bool any = false;
    for (int32_t i = static_cast<int32_t>(lo); i <= static_cast<int32_t>(hi); ++i, dx += step) {
      const I x = static_cast<I>(dx);
      const int64_t r2 = static_cast<int64_t>(x) * x + dy2;
      if (r2 > reach2) continue;
      const int64_t h_v = zlow_v + (flat ? 0 : sweep_profile_v(t, min_of(r2, t.r2_u)));
      any |= shaft_above ? sweep_cut_dexel<H>(g, &wt[i], &wb[i], h_v, ct_lsb, true) : s.cut(wt, wb, i, h_v, 0, 0);
    }
    return any;
  };
  if constexpr (W == 32) {
    if (detail::fits_i32(dx_lo) && detail::fits_i32(dx_hi) && detail::fits_i32(s.p_u))
      return columns(static_cast<int32_t>(dx_lo));
  }
  return columns(dx_lo);
}

// A general direction's row: u and v walked from their q30 accumulators
// (du, dv a column); I (their type) is int32_t in 32-bit words where the
// ranges allow it (PieceRows::narrow_fits), so that squares and slope
// products are one 32 x 32 -> 64-bit multiply on a 32-bit CPU, and the
// accumulator is RoundWalk30Split (core/cut/sweep_cut.h).
template <class H, int W>
__attribute__((always_inline)) inline bool general_row(const PieceRows<H>& s, int64_t lo, int64_t hi, int64_t dy_row_u,
                                                      int64_t u_acc, int64_t v_acc, int64_t du, int64_t dv, H* const wt,
                                                      H* const wb, uint64_t* floor_skips) {
  const SweepTool& t = *s.t;
  const SweepLine& lp = *s.lp;
  const SlopeMul slope_v{lp.slope_v_q32};
  auto columns = [&](auto uw, auto vw) {
    using I = decltype(uw.value());
    uw.start(u_acc, du);
    vw.start(v_acc, dv);
    // u < wr.lo and u - l > wr.hi, as comparisons of u alone.
    const I w_lo = static_cast<I>(s.wr.lo), w_hi_end = static_cast<I>(s.wr.hi + lp.len_u);
    const I len = static_cast<I>(lp.len_u);
    bool any = false;
    uint32_t skips = 0;  // floor_skips of the row: at most nx
    // Column indices within [0, nx) fit int32.
    for (int32_t i = static_cast<int32_t>(lo); i <= static_cast<int32_t>(hi); ++i, uw.next(), vw.next()) {
      const I u = uw.value(), v = vw.value();
      // |v_acc| <= (R + 1) 2^30 (NarrowRows), so v^2 < reach2 = (R + 2)^2.
      const int64_t v2 = min_of(static_cast<int64_t>(v) * v, t.r2_u);
      // Under the floor (ball_floor_of) the top is lower than any height
      // this piece computes here: nothing to cut, and no root.
      if (s.cull) {
        const int64_t floor_v = s.ball_floor_v + slope_v(u) + sweep_bowl_v(t, v2);
        if (floor_v >= sweep_keep_v(wt[i])) {
          ++skips;
          continue;
        }
      }
      // w* in [wr.lo, wr.hi]: outside, the clamp is decided without
      // computing w* (a square root for ramps).
      // The lowest point: behind the start (w = u), beyond the end
      // (w = u - l) or on the flank (w = w*), as clamp(w*, u - l, u).
      I w = 0;
      int64_t rho = 0;
      int side = 0;
      if (u < w_lo) {
        side = -1;
      } else if (u > w_hi_end) {
        side = 1;
      } else {
        if (s.ball) {  // one root for w* and the flank (best_w_rho's ball case)
          rho = rho_of(t, v2);
          w = lp.level ? 0 : static_cast<I>(mul_shift_fit(rho, lp.ball_sin_q30, 30));
        } else if (lp.level) {
          w = 0;
        } else {
          // Inside its cone the V-bit's w* needs no chord (best_w_rho's
          // own test; where it fails, best_w takes the rim).
          // (|ws| <= R first: the square of a w far past the rim overflows.)
          int64_t ws = 0;
          if (s.vbit_cone) ws = mul_shift(v < 0 ? -static_cast<int64_t>(v) : v, lp.vbit_c1_q30, 30);
          const bool in_cone = s.vbit_cone && (ws < 0 ? -ws : ws) <= t.r_u && ws * ws + v2 <= t.r2_u;
          w = static_cast<I>(in_cone ? ws : best_w(t, lp, v, v2));
        }
        side = u < w ? -1 : (u - len > w ? 1 : 0);
      }
      if (side < 0) {
        if (!s.start_ok(u, v, i, dy_row_u)) continue;
        w = u;
      } else if (side > 0) {
        if (!s.caps.end) continue;
        w = u - len;
      }
      // A cap's distance from its centre is the grid frame's, exactly, as
      // the tool standing there has it (plunge_row, cut_tool_at): u and v
      // are walked in the piece's turned frame and rounded, and on a bull
      // nose's rim, where the torus stands vertical, 1 U off in r moves the
      // height by sqrt(2 rc U), so a cap and the standing tool would
      // differ there (a run split at that joint would not be the whole).
      int64_t r2;
      if (side == 0) {
        r2 = static_cast<int64_t>(w) * w + v2;
      } else {
        // (Offsets from either end are below 2^31 U, sweep.h: in 32-bit
        // words one 32 x 32 -> 64-bit multiply each.)
        const I dx = static_cast<I>(s.dx0_u + (i - s.i_first) * s.p_u - (side > 0 ? s.end_dx_u : 0));
        const I dy = static_cast<I>(dy_row_u - (side > 0 ? s.end_dy_u : 0));
        r2 = static_cast<int64_t>(dx) * dx + static_cast<int64_t>(dy) * dy;
      }
      if (r2 > s.reach2) continue;
      const int64_t h_v = side == 0 && s.ball ? lp.za_v + slope_v(u) + ball_flank_v(t, lp, rho)
                                              : lp.za_v + slope_v(u - w) + sweep_profile_v(t, min_of(r2, t.r2_u));
      any |= s.shaft_above ? sweep_cut_dexel<H>(s.g, &wt[i], &wb[i], h_v, s.ct_lsb, true) : s.cut(wt, wb, i, h_v, u, v2);
    }
    *floor_skips += skips;
    return any;
  };
  if constexpr (W == 32) {
    if (s.narrow_fits) return columns(RoundWalk30Split{}, RoundWalk30Split{});
  }
  return columns(RoundWalk30Acc<int64_t>{}, RoundWalk30Acc<int64_t>{});
}

// The flank of a row along x, columns f_lo .. f_hi (u from u0, a step
// apart): every lowest point at w = w*, heights linear in u from flank_v.
// cut_rows(i, h_v, u) cuts a column of the row and of its mirror (mt, mb,
// when not null) and keeps what changed; the rest is returned as bits (bit 0:
// the row changed, bit 1: the mirror).
template <class H, class F>
__attribute__((always_inline)) inline unsigned along_x_flank(const PieceRows<H>& s, F& cut_rows, int64_t f_lo,
                                                             int64_t f_hi, int64_t u0, int64_t flank_v, H* wt, H* wb,
                                                             H* mt, H* mb, int64_t v2) {
  const int64_t step = s.x_step;
  if (!s.x_run_fits) return flank_exact<H>(s, wt, wb, mt, mb, v2, f_lo, f_hi, u0, step, flank_v, kRunMaxV);
  // Linear heights: a q16 DDA (drift below 2^-16 V a column).
  int64_t h_q16 = (flank_v + mul_shift_fit(u0, s.lp->slope_v_q32, 32)) * 65536;
  const int64_t dh_q16 = s.x_dh_q16;
  const int64_t round = static_cast<int64_t>(1) << (16 + kSweepVBits - 1);
  const int64_t cb_first = (h_q16 + round) >> (16 + kSweepVBits);
  const int64_t cb_last = (h_q16 + (f_hi - f_lo) * dh_q16 + round) >> (16 + kSweepVBits);
  if (s.g->bottoms_zero && s.shaft_above && min_of(cb_first, cb_last) >= 1) {
    // Every bottom is 0 and every cb >= 1: figure 2 reduces to min().
    if (mt) {
      const int64_t n = f_hi - f_lo + 1;
      return dh_q16 == 0 ? min_level_pair(wt + f_lo, mt + f_lo, n, static_cast<H>(min_of(cb_first, s.hmax)))
                         : min_run_pair(wt + f_lo, mt + f_lo, n, h_q16 + round, dh_q16);
    }
    const bool c = dh_q16 == 0 ? min_level(wt + f_lo, wt + f_hi + 1, static_cast<H>(min_of(cb_first, s.hmax)))
                               : min_run(wt + f_lo, wt + f_hi + 1, h_q16 + round, dh_q16);
    return c ? 1u : 0u;
  }
  for (int64_t i = f_lo; i <= f_hi; ++i, h_q16 += dh_q16) cut_rows(i, h_q16 >> 16, u0 + (i - f_lo) * step);
  return 0;  // cut_rows keeps its own
}

// A row along x (x-parallel): v, w*(v) and the flank's height F(w*) - m*w*
// are constants of the row; only the ends of the row need the profile per
// column. One form for both word widths: its columns are a q16 DDA. Bit 0
// of the result: the row changed; bit 1: its mirror.
template <class H>
__attribute__((always_inline)) inline unsigned along_x_row(const PieceRows<H>& s, int64_t lo, int64_t hi, int64_t jm,
                                                           bool pair, int64_t dy_row_u, int64_t v_acc, H* const wt,
                                                           H* const wb) {
  const SweepTool& t = *s.t;
  const SweepLine& lp = *s.lp;
  const PieceCaps& caps = s.caps;
  const int64_t v = (v_acc + kQ30 / 2) >> 30;
  if (v * v > s.reach2) return 0;
  const int64_t v2 = min_of(v * v, t.r2_u);
  // One square root a row: rho serves w* of this piece and of the
  // previous one, and the ball's flank.
  const bool need_rho = !lp.level || (s.collinear && !caps.prev->level) || t.kind == ToolKind::kBall;
  const int64_t rho = need_rho ? rho_memo(t, v2, caps.roots) : 0;
  const int64_t ws = best_w_rho(t, lp, v, v2, rho);
  const int64_t ws2 = ws * ws + v2;
  const int64_t flank_v = t.kind == ToolKind::kBall
                              ? lp.za_v + ball_flank_v(t, lp, rho)
                              : lp.za_v - mul_shift_fit(ws, lp.slope_v_q32, 32) + sweep_profile_v(t, min_of(ws2, t.r2_u));
  const bool flank_reaches = ws2 <= s.reach2;
  // Collinear wedge: the previous piece's w* on this row, once.
  const int64_t ws_prev = s.collinear ? best_w_rho(t, *caps.prev, v, v2, rho) : 0;
  // Split the row into the flank, where the lowest point is w = w*,
  // and the two ends.
  const int64_t step = s.x_step, u_lo = s.x_u_lo;
  int64_t f_lo, f_hi;  // flank columns: ws <= u <= ws + l
  if (step > 0) {
    f_lo = lo + div_ceil(ws - u_lo, step);
    f_hi = lo + div_floor(ws + lp.len_u - u_lo, step);
  } else {
    f_lo = lo + div_ceil(ws + lp.len_u - u_lo, step);
    f_hi = lo + div_floor(ws - u_lo, step);
  }
  f_lo = clamp(f_lo, lo, hi + 1);
  f_hi = clamp(f_hi, f_lo - 1, hi);
  // The mirror row, when there is one.
  H* const mt = pair ? s.g->top + s.g->index(0, static_cast<int32_t>(jm)) : nullptr;
  H* const mb = pair ? s.g->bottom + s.g->index(0, static_cast<int32_t>(jm)) : nullptr;
  // Cuts column i of the row, and of its mirror, at the same height.
  bool row_changed = false, mirror_changed = false;
  auto cut_rows = [&](int64_t i, int64_t h_v, int64_t u) {
    row_changed |= s.cut(wt, wb, i, h_v, u, v2);
    if (pair) mirror_changed |= s.cut(mt, mb, i, h_v, u, v2);
  };
  auto side = [&](int64_t i) {
    const int64_t u = u_lo + (i - lo) * step;
    int64_t w;
    if (u < ws) {
      if (s.collinear ? u < ws_prev : !s.start_ok(u, v, i, dy_row_u)) return;
      w = u;
    } else {
      if (!caps.end) return;
      w = u - lp.len_u;
    }
    const int64_t r2 = w * w + v2;
    if (r2 > s.reach2) return;
    const int64_t h_v = lp.za_v + mul_shift_fit(u - w, lp.slope_v_q32, 32) + sweep_profile_v(t, min_of(r2, t.r2_u));
    cut_rows(i, h_v, u);
  };
  // Only visit the ends that can cut: the start side unless the
  // previous piece's band covers it (collinear: w*_prev >= w*), the end
  // side only with the end cap.
  const bool start_side =
      caps.start == StartCap::kCut || (caps.start == StartCap::kWedge && (!s.collinear || ws_prev < ws));
  const bool low_side = step > 0 ? start_side : caps.end;   // columns lo .. f_lo - 1
  const bool high_side = step > 0 ? caps.end : start_side;  // columns f_hi + 1 .. hi
  // Each end from the flank outwards. The start side's u falls, and a
  // collinear wedge ends at its first column behind ws_prev (side()
  // leaves those: the previous piece's lowest point is inside it), so
  // the loops stop there; the end side (stop: none) goes on.
  const int64_t stop_u = s.collinear && s.tune->wedge_stops ? ws_prev : INT64_MIN;
  if (low_side)
    for (int64_t i = f_lo - 1; i >= lo && (step < 0 || u_lo + (i - lo) * step >= stop_u); --i) side(i);
  unsigned bits = 0;
  if (flank_reaches && f_lo <= f_hi)
    bits = along_x_flank(s, cut_rows, f_lo, f_hi, u_lo + (f_lo - lo) * step, flank_v, wt, wb, mt, mb, v2);
  if (high_side)
    for (int64_t i = f_hi + 1; i <= hi && (step > 0 || u_lo + (i - lo) * step >= stop_u); ++i) side(i);
  return bits | (row_changed ? 1u : 0u) | (mirror_changed ? 2u : 0u);
}

// A straight piece a -> b with the caps `caps`: the set-up (piece_frame,
// piece_rows), then row after row one of the row kernels. u_acc and v_acc
// at column i_first of row j are exact integers: in 32-bit words walked
// from row to row (dy grows by the pitch), instead of four 64 x 64-bit
// products a row (within the box |u|, |v| < 2^31.2 U, and a step is p_u
// 2^30 < 2^62 for a pitch up to a metre: the step past the last row stays
// within int64); in 64-bit words the products, which cost as much as the
// walk and keep two registers fewer live across the column loops.
template <class H, int W>
PieceEnd sweep_piece(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, PointNm a, PointNm b, CutStats* st,
                     PieceCaps caps, SweepLine* lp_out) {
  PieceRows<H> s;
  PieceEnd result;
  if (!piece_frame<H, W>(g, t, tune, a, b, st, caps, lp_out, &s, &result)) return result;
  NarrowRows across, along;
  piece_rows(&s, &across, &along, st);
  const SweepLine& lp = *lp_out;
  const int64_t p = s.p, p_u = s.p_u;
  const int64_t du = lp.plunge ? 0 : p_u * lp.ex_q30, dv = lp.plunge ? 0 : -p_u * lp.ey_q30;
  const int64_t du_row = lp.plunge ? 0 : p_u * lp.ey_q30, dv_row = lp.plunge ? 0 : p_u * lp.ex_q30;
  int64_t u_row = 0, v_row = 0;  // 32-bit words: row j_first's, walked
  if (W == 32 && !lp.plunge) {
    const int64_t dy_first_u = (g->y0_nm + s.j_first * p - s.o.y_nm) * kSweepUnitsPerNm;
    u_row = s.dx0_u * lp.ex_q30 + dy_first_u * lp.ey_q30;
    v_row = dy_first_u * lp.ex_q30 - s.dx0_u * lp.ey_q30;
  }
  auto next_row = [&] {
    if (W == 32) {
      u_row += du_row;
      v_row += dv_row;
    }
    if (s.walk) {
      across.next();
      along.next();
    }
  };
  bool changed = false;
  int64_t ch_i0 = g->nx, ch_i1 = -1, ch_j0 = g->ny, ch_j1 = -1;
  uint64_t floor_skips = 0;
  for (int64_t j = s.j_first; j <= s.j_last; ++j, next_row()) {
    // The row of the pair that comes first does both.
    const int64_t jm = s.mirror_sum - j;
    if (s.mirrored && jm < j && jm >= s.j_first) continue;
    const bool pair = s.mirrored && jm > j && jm <= s.j_last;
    const int64_t dy_row_u = (g->y0_nm + j * p - s.o.y_nm) * kSweepUnitsPerNm;
    int64_t lo = s.i_first, hi = s.i_last;
    int64_t u_acc = u_row, v_acc = v_row;
    if (!lp.plunge) {
      if (W != 32) {
        // u = (P - A) . e and v = (P - A) x e, in U * 2^30.
        u_acc = s.dx0_u * lp.ex_q30 + dy_row_u * lp.ey_q30;
        v_acc = dy_row_u * lp.ex_q30 - s.dx0_u * lp.ey_q30;
      }
      if (s.along_x) {
        if (v_acc < -s.r_q30 || v_acc > s.r_q30) continue;
        lo = s.x_lo;
        hi = s.x_hi;
      } else {
        across.apply(s.i_first, &lo, &hi);
        along.apply(s.i_first, &lo, &hi);
      }
    }
    if (lo > hi) continue;
    st->dexel_updates += static_cast<uint64_t>(hi - lo + 1) * (pair ? 2 : 1);
    if (st->log) {
      st->log->add(static_cast<int32_t>(j), static_cast<int32_t>(lo), static_cast<int32_t>(hi));
      if (pair) st->log->add(static_cast<int32_t>(jm), static_cast<int32_t>(lo), static_cast<int32_t>(hi));
    }
    u_acc += (lo - s.i_first) * du;
    v_acc += (lo - s.i_first) * dv;
    H* const wt = g->top + g->index(0, static_cast<int32_t>(j));
    H* const wb = g->bottom + g->index(0, static_cast<int32_t>(j));
    // Bit 0: the row changed; bit 1: its mirror.
    const unsigned bits = lp.plunge ? (plunge_row<H, W>(s, lo, hi, dy_row_u, wt, wb) ? 1u : 0u)
                          : dv == 0 ? along_x_row(s, lo, hi, jm, pair, dy_row_u, v_acc, wt, wb)
                                    : (general_row<H, W>(s, lo, hi, dy_row_u, u_acc, v_acc, du, dv, wt, wb, &floor_skips)
                                           ? 1u
                                           : 0u);
    if (bits) {
      const bool row_changed = (bits & 1u) != 0, mirror_changed = (bits & 2u) != 0;
      changed = true;
      ch_i0 = min_of(ch_i0, lo);
      ch_i1 = max_of(ch_i1, hi);
      ch_j0 = min_of(ch_j0, row_changed ? j : jm);
      ch_j1 = max_of(ch_j1, mirror_changed ? jm : j);
    }
  }
  st->floor_skips += floor_skips;
  if (changed)
    g->dirty.include(GridRect{static_cast<int32_t>(ch_i0), static_cast<int32_t>(ch_j0),
                              static_cast<int32_t>(ch_i1 + 1), static_cast<int32_t>(ch_j1 + 1)});
  return result;
}

// Splits a -> b so that no piece is longer than kMaxPieceNm horizontally
// and calls piece(from, to, first) for each.
template <class F>
void for_each_piece(PointNm a, PointNm b, F piece) {
  const uint64_t span = max_of(abs_u64(b.x_nm - a.x_nm), abs_u64(b.y_nm - a.y_nm));
  const int64_t pieces = static_cast<int64_t>(span / static_cast<uint64_t>(kMaxPieceNm)) + 1;
  PointNm from = a;
  for (int64_t k = 1; k <= pieces; ++k) {
    PointNm to = b;
    if (k < pieces) {
      to.x_nm = a.x_nm + muldiv_floor(b.x_nm - a.x_nm, k, pieces);
      to.y_nm = a.y_nm + muldiv_floor(b.y_nm - a.y_nm, k, pieces);
      to.z_nm = a.z_nm + muldiv_floor(b.z_nm - a.z_nm, k, pieces);
    }
    piece(from, to, k == 1);
    from = to;
  }
}

// A bull-nose piece of chain c (and the last one) use the chain's memo,
// with row slots (core/cut/sweep_internal.h, BullFlankMemo) on a grid of
// pitch_nm > 0 (half a pitch is 2 p U), hashed ones for 0
// (SweepTuning::bull_row_shortcuts off); the pieces' ways alternate. Not
// inlined: the other tools' chains compile as without it.
__attribute__((noinline)) void bull_chain_memo(int64_t pitch_nm, SweepChainParts* c, SweepLine* lp) {
  lp->bull_memo = c->last.bull_memo = &c->bull_memo;
  const uint64_t half_u = 2 * static_cast<uint64_t>(pitch_nm);
  c->bull_memo.row_inv_q32 = pitch_nm > 0 ? ((static_cast<uint64_t>(1) << 32) + half_u - 1) / half_u : 0;
  lp->bull_way = c->bull_memo.next_way;
  c->bull_memo.next_way ^= 1;
}

}  // namespace
#pragma GCC diagnostic pop

template <class H, int W>
void sweep_line_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, PointNm a, PointNm b, CutStats* st,
                  bool start_cap) {
  for_each_piece(clamp_point(a), clamp_point(b), [&](PointNm from, PointNm to, bool first) {
    SweepLine lp;
    const StartCap start = first && start_cap ? StartCap::kCut : StartCap::kSkip;
    sweep_piece<H, W>(g, t, tune, from, to, st, PieceCaps{start, nullptr, true, nullptr}, &lp);
  });
}

template <class H, int W>
void sweep_chain_end_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, CutStats* st, SweepChain* c) {
  if (c->state != SweepChain::State::kPending) return;
  cut_tool_at<H, W>(g, t, tune, c->end, st);
  c->state = SweepChain::State::kCovered;
}

template <class H, int W>
void sweep_chain_line_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, PointNm a, PointNm b,
                        CutStats* st, SweepChain* c) {
  a = clamp_point(a);
  b = clamp_point(b);
  if (!(c->end == a)) {
    sweep_chain_end_w<H, W>(g, t, tune, st, c);
    c->state = SweepChain::State::kFresh;
  }
  SweepChainParts* const parts = chain_parts(c);
  for_each_piece(a, b, [&](PointNm from, PointNm to, bool) {
    const StartCap start = c->state == SweepChain::State::kFresh     ? StartCap::kCut
                           : c->state == SweepChain::State::kCovered ? StartCap::kSkip
                                                                     : StartCap::kWedge;
    SweepLine lp;
    // The bull nose's w* through the chain's memo, for this piece and the last.
    if (t.kind == ToolKind::kBullNose)
      bull_chain_memo(tune.bull_row_shortcuts ? g->pitch_nm : 0, parts, &lp);
    else
      lp.bull_memo = parts->last.bull_memo = nullptr;
    const PieceEnd e =
        sweep_piece<H, W>(g, t, tune, from, to, st, PieceCaps{start, &parts->last, false, &parts->roots}, &lp);
    c->state = e == PieceEnd::kPending ? SweepChain::State::kPending
               : e == PieceEnd::kCovered ? SweepChain::State::kCovered
                                         : SweepChain::State::kFresh;
    parts->last = lp;
    c->end = to;
  });
}

// The _w entry points above for every height type in W-bit words.
#define DEXMILL_SWEEP_LINE_W_INSTANTIATE(H, W)                                                                     \
  template void sweep_line_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, PointNm, PointNm, CutStats*, \
                                   bool);                                                                           \
  template void sweep_chain_line_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, PointNm, PointNm,     \
                                         CutStats*, SweepChain*);                                                   \
  template void sweep_chain_end_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, CutStats*, SweepChain*);
#define DEXMILL_SWEEP_LINE_W_INSTANTIATE_ALL(W) \
  DEXMILL_SWEEP_LINE_W_INSTANTIATE(uint8_t, W)  \
  DEXMILL_SWEEP_LINE_W_INSTANTIATE(uint16_t, W) \
  DEXMILL_SWEEP_LINE_W_INSTANTIATE(uint32_t, W)

}  // namespace dexmill

#endif
