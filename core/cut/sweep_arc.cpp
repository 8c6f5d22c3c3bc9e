// Swept envelope of arcs (core/cut/sweep.h).
//
// A level arc in the XY plane with a ball or flat end is cut exactly per
// column: the lowest point of the tool over the arc is the tool at the point
// of the arc nearest the column (the profile rises with distance), and that
// distance is closed form: |rho - Ra| when the column's direction from the
// centre lies in the arc's sector, else the distance to the nearer end
// point. Arcs are taken a quarter turn at a time (core/canon/arc_chords.h places
// the pieces), which keeps the sector test to two cross products.
//
// Everything else (helices, G18/G19 planes, bull nose and V-bit, radii over
// 2^27 nm) is cut as chords of sagitta <= kArcChordSagittaNm, each swept
// exactly: the tool path is then within 1 um + 7 nm of the arc.
//
// Ranges (core/cut/sweep.h; U = nm / 4): an exact arc's radius ra <= 2^27
// nm = 2^29 U and R <= 2^30 U, so every column visited lies in its piece's
// ring, |q| <= ro <= ra + R + 11 < 2^31 U (ring_runs visits the whole box
// only for ro >= 2^31: never here), and |q|^2 < 2^62. Products:
//   ring_runs: ro^2, qy^2 < 2^62 (|qy| <= ro first), ri^2 likewise;
//   cross(a, q): |a| <= 2^29 + the start's offset, |q| < 2^31: each
//     product < 2^60.1, the difference < 2^61.1, times dir;
//   level_piece: (rho - ra)^2 < 2^62 (rho <= |q|); |q - A|^2, |q - B|^2 <=
//     (ro + ra + 1)^2 <= (2^31 + 12)^2 < 2^62.1 (2 ra + R <= 2^31);
//   helix_piece: rho2 < 2^62, ra^2 < 2^58, 2 rho ra < 2^61, 4 t1 t2 = 4 rho
//     ra sin^2 < 2^62, (rho - ra)^2 <= R^2; kappa, kk, qq by muldiv
//     (128-bit, saturating), kk < 2^46 (q30, the exactness test), disc
//     saturated; z0 + dz s / span + P < 2^56 V;
//   chords: sweep_line's ranges (core/cut/sweep_piece.h).
#include "core/cut/arc_walk.h"
#include "core/cut/stamp.h"
#include "core/cut/sweep_cut.h"
#include "core/cut/sweep_internal.h"
#include "core/math/fixed.h"
#include "core/canon/arc_chords.h"

namespace dexmill {
namespace {

constexpr int64_t kMaxExactRadiusNm = static_cast<int64_t>(1) << 27;

int64_t cross(int64_t ax, int64_t ay, int64_t bx, int64_t by) { return ax * by - ay * bx; }

// What level arcs and helices share: the tip's height range [zlow_v,
// zhigh_v] against the grid's, the shaft top, the dexels of a box around the
// centre C (U relative to C, widened by the tool), and the bookkeeping
// (counts, span log, one dirty-rectangle update a row), visiting only the
// box's columns within the piece's ring (ring_runs). column(qx, qy,
// keep_v, &h_v, ct_v) gets a column's offset from C (U) and gives the lowest
// tool height there (V above z0), or kOut when the tool does not reach it or
// the column is left to another move. keep_v: a height at or above which the
// column would not change (INT64_MAX where that may not be assumed); a
// column that knows its height is that high without computing it answers
// kUnderFloor. When the shaft is below some top, ct_v is not null and holds
// zlow_v: a helix raises it to the tip height of the highest position
// covering the column (figure 2's ct is that plus the length).
enum class ArcColumn : uint8_t { kOut, kCut, kUnderFloor };

// The ring of a piece: every column it may cut lies at a distance from the
// centre within [ri, ro] (U); ri = 0 when there is no hole.
struct ArcRing {
  int64_t ri, ro;
};

// The columns of one row whose offset qx from the centre (qx0 + k p_u at
// column i_first + k) keeps qx^2 + qy^2 within the ring: up to two runs,
// [lo[0], hi[0]] and [lo[1], hi[1]] (empty when lo > hi), clipped to
// [i_first, i_last]. Exact: rounding only widens the runs.
struct RingRuns {
  int64_t lo[2], hi[2];
};
RingRuns ring_runs(const ArcRing& ring, int64_t qy, int64_t qx0, int64_t p_u, int64_t i_first, int64_t i_last) {
  RingRuns rr{{i_first, i_first}, {i_last, i_first - 1}};  // the second run empty
  // Squares below 2^62: a ring wider than 2^31 U (a start point far off its
  // circle) visits its whole box.
  if (ring.ro >= (static_cast<int64_t>(1) << 31)) return rr;
  if (qy > ring.ro || qy < -ring.ro) {
    rr.hi[0] = i_first - 1;
    return rr;
  }
  const int64_t qy2 = qy * qy, ro2 = ring.ro * ring.ro;
  // |qx| <= xo keeps qx^2 + qy^2 <= ro^2.
  const int64_t xo = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(ro2 - qy2)));
  // |qx| >= xi keeps qx^2 + qy^2 >= ri^2: xi = ceil(sqrt(ri^2 - qy^2)).
  int64_t xi = 0;
  const int64_t hole2 = ring.ri * ring.ri - qy2;
  if (hole2 > 0) {
    xi = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(hole2)));
    if (xi * xi < hole2) ++xi;
  }
  // Column range of qx in [a, b].
  auto cols = [&](int64_t a, int64_t b, int k) {
    rr.lo[k] = max_of(i_first, i_first + div_ceil(a - qx0, p_u));
    rr.hi[k] = min_of(i_last, i_first + div_floor(b - qx0, p_u));
  };
  if (xi == 0) {
    cols(-xo, xo, 0);
  } else {
    cols(-xo, -xi, 0);
    cols(xi, xo, 1);
  }
  return rr;
}

template <class H, class F>
void cut_arc_box(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, CutStats* st, int64_t cx_nm, int64_t cy_nm, int64_t x0,
                 int64_t y0, int64_t x1, int64_t y1, const ArcRing& ring, int64_t zlow_v, int64_t zhigh_v, F column) {
  const int64_t hmax = height_max<H>();
  if (zlow_v >= (hmax << kSweepVBits) || zhigh_v + t.len_v <= 0) return;
  const int64_t ct_lsb = (zlow_v + t.len_v) >> kSweepVBits;
  const bool shaft_above = ct_lsb >= g->top_bound_lsb;  // see DexelGrid::top_bound_lsb
  // Only where a cut is a min() does a tool height at or above the top
  // leave the column as it is.
  const bool may_keep = shaft_above && tune.skip_under_floor;
  uint64_t floor_skips = 0;
  SweepColumns box;
  if (!sweep_columns(*g, t, cx_nm + x0 / kSweepUnitsPerNm, cx_nm + x1 / kSweepUnitsPerNm, cy_nm + y0 / kSweepUnitsPerNm,
                     cy_nm + y1 / kSweepUnitsPerNm, &box))
    return;
  const int64_t p = g->pitch_nm;
  const int64_t i_first = box.i_first, i_last = box.i_last, j_first = box.j_first, j_last = box.j_last;
  st->instances++;
  const int64_t p_u = p * kSweepUnitsPerNm;
  const int64_t qx0 = (g->x0_nm + i_first * p - cx_nm) * kSweepUnitsPerNm;
  for (int64_t j = j_first; j <= j_last; ++j) {
    const int64_t qy = (g->y0_nm + j * p - cy_nm) * kSweepUnitsPerNm;
    const RingRuns rr = ring_runs(ring, qy, qx0, p_u, i_first, i_last);
    H* wt = g->top + g->index(0, static_cast<int32_t>(j));
    H* wb = g->bottom + g->index(0, static_cast<int32_t>(j));
    int64_t ch0 = i_last + 1, ch1 = i_first - 1;
    for (int k = 0; k < 2; ++k) {
      if (rr.lo[k] > rr.hi[k]) continue;
      st->dexel_updates += static_cast<uint64_t>(rr.hi[k] - rr.lo[k] + 1);
      if (st->log) st->log->add(static_cast<int32_t>(j), static_cast<int32_t>(rr.lo[k]), static_cast<int32_t>(rr.hi[k]));
      int64_t qx = qx0 + (rr.lo[k] - i_first) * p_u;
      for (int64_t i = rr.lo[k]; i <= rr.hi[k]; ++i, qx += p_u) {
        int64_t h_v, zct_v = zlow_v;
        const int64_t keep_v = may_keep ? sweep_keep_v(wt[i]) : INT64_MAX;
        const ArcColumn c = column(qx, qy, keep_v, &h_v, shaft_above ? nullptr : &zct_v);
        if (c != ArcColumn::kCut) {
          floor_skips += c == ArcColumn::kUnderFloor ? 1 : 0;
          continue;
        }
        const int64_t ct = shaft_above ? ct_lsb : (zct_v + t.len_v) >> kSweepVBits;
        if (sweep_cut_dexel<H>(g, &wt[i], &wb[i], h_v, ct, shaft_above)) {
          ch0 = min_of(ch0, i);
          ch1 = i;
        }
      }
    }
    if (ch0 <= ch1)
      g->dirty.include(GridRect{static_cast<int32_t>(ch0), static_cast<int32_t>(j), static_cast<int32_t>(ch1 + 1),
                                static_cast<int32_t>(j + 1)});
  }
  st->floor_skips += floor_skips;
}

// floor(|(x, y)|), U.
int64_t radius_of(int64_t x, int64_t y) {
  return static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(x * x + y * y)));
}

// The bounding box of a piece of at most a quarter turn from A to B about
// the centre, radius ra (U relative to the centre, dir = +1 counterclockwise):
// its end points and any axis extreme inside its sector, widened by how far
// A is off the circle (the interpreter's tolerance; ra_a = floor(|A|)): the
// arc itself starts at ra A / |A|.
struct PieceBox {
  int64_t x0, y0, x1, y1;
};
PieceBox piece_box(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t ra, int64_t ra_a, int dir) {
  const int64_t off = (ra > ra_a ? ra - ra_a : ra_a - ra) + 2;
  PieceBox b{min_of(ax, bx) - off, min_of(ay, by) - off, max_of(ax, bx) + off, max_of(ay, by) + off};
  const int64_t ext[4][2] = {{ra, 0}, {0, ra}, {-ra, 0}, {0, -ra}};
  for (const auto& e : ext) {
    if (cross(ax, ay, e[0], e[1]) * dir >= 0 && cross(e[0], e[1], bx, by) * dir >= 0) {
      b.x0 = min_of(b.x0, e[0]);
      b.x1 = max_of(b.x1, e[0]);
      b.y0 = min_of(b.y0, e[1]);
      b.y1 = max_of(b.y1, e[1]);
    }
  }
  return b;
}

// A level quarter-turn (at most) piece from A to B about C, radius ra, all in
// U relative to C; dir = +1 counterclockwise.
template <class H>
void level_piece(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, int64_t cx_nm, int64_t cy_nm, int64_t ax, int64_t ay,
                 int64_t bx, int64_t by, int64_t ra, int dir, int64_t z_nm, CutStats* st, bool start_cap) {
  const int64_t z_v = sweep_height_v(*g, z_nm);
  const int64_t reach2 = sweep_reach2(t);
  // A cut column is within reach (R + 2, sweep_reach2) of the circle
  // (rho = floor(|q|) within it of ra) or of an end: A may sit off the
  // circle by the interpreter's tolerance (|A| in [ra_a, ra_a + 1)), B by
  // its rounding to a nm (under 2 nm, 8 U).
  const int64_t ra_a = radius_of(ax, ay);
  const PieceBox box = piece_box(ax, ay, bx, by, ra, ra_a, dir);
  const int64_t r_reach = t.r_u + 2, slack = 8;
  const ArcRing ring{max_of<int64_t>(0, min_of(ra, ra_a) - r_reach - slack), max_of(ra, ra_a + 1) + r_reach + 1 + slack};
  const bool ball = t.kind == ToolKind::kBall;
  cut_arc_box(g, t, tune, st, cx_nm, cy_nm, box.x0, box.y0, box.x1, box.y1, ring, z_v, z_v,
              [&](int64_t qx, int64_t qy, int64_t keep_v, int64_t* h_v, int64_t*) {
    const bool after_a = cross(ax, ay, qx, qy) * dir >= 0, before_b = cross(qx, qy, bx, by) * dir >= 0;
    int64_t d2;
    if (after_a && before_b) {
      const int64_t rho = radius_of(qx, qy);
      d2 = (rho - ra) * (rho - ra);
    } else {
      const int64_t da2 = (qx - ax) * (qx - ax) + (qy - ay) * (qy - ay);
      const int64_t db2 = (qx - bx) * (qx - bx) + (qy - by) * (qy - by);
      // Behind the start, where the tool standing at A is lowest: already
      // cut by the move that ended there.
      if (!start_cap && da2 < db2) return ArcColumn::kOut;
      d2 = min_of(da2, db2);
    }
    if (d2 > reach2) return ArcColumn::kOut;
    // The ball's profile is at least its paraboloid less 1 V (the level case
    // of ball_floor_of, core/cut/sweep_piece.h): at or above keep_v, no root.
    if (ball && z_v + sweep_bowl_v(t, min_of(d2, t.r2_u)) - 1 >= keep_v) return ArcColumn::kUnderFloor;
    *h_v = z_v + sweep_profile_v(t, min_of(d2, t.r2_u));
    return ArcColumn::kCut;
  });
}

// A helical piece (at most a quarter turn) from A to B about C, radius ra,
// tip height z0 -> z1 linear in the angle; flat or ball end; ra > R for the
// ball (the reach window then spans less than a half turn, where the ball's
// lowest point is convex in the angle). Per column, with s the angle along
// the piece, s_P the column's own angle and r(s) its distance to the axis:
//   reach: |s - s_P| <= alpha, cos(alpha) = (rho^2 + ra^2 - R^2) / (2 rho ra);
//   flat: the reachable end of the window in the descending direction;
//   ball: z(s) + R - sqrt(R^2 - r(s)^2) is stationary where
//         cos(s - s_P) = -kk + sqrt(kk^2 - kk qq + 1), kk = kappa^2 / (rho ra),
//         qq = (R^2 - rho^2 - ra^2) / (rho ra), kappa = dz/ds per radian,
//         clamped to the window (convexity makes that the minimum).
// Angles are CORDIC binary angles (2 bam: 3e-9 rad), so the column is met
// within ra * 3e-9 of its place: inside the backward bound for ra <= 2^27 nm.
template <class H>
void helix_piece(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, int64_t cx_nm, int64_t cy_nm, int64_t ax, int64_t ay,
                 int64_t bx, int64_t by, int64_t ra, int dir, int64_t z0_nm, int64_t z1_nm, CutStats* st,
                 bool start_cap) {
  const int64_t z0_v = sweep_height_v(*g, z0_nm);
  const int64_t z1_v = sweep_height_v(*g, z1_nm);
  const int64_t zlow = min_of(z0_v, z1_v), zhigh = max_of(z0_v, z1_v);
  const uint32_t phi_a = atan2_bam(ay, ax);
  int64_t span = dir * static_cast<int64_t>(static_cast<int32_t>(atan2_bam(by, bx) - phi_a));
  if (span <= 0) span += static_cast<int64_t>(1) << 32;  // a piece is at most a quarter turn
  const int64_t dz_v = z1_v - z0_v;
  const int64_t dz_u = (z1_nm - z0_nm) * kSweepUnitsPerNm;
  // kappa = dz/ds in U per radian: dz_u * 2^32 / (2 pi span).
  constexpr int64_t kTwoPiQ28 = 1686629713;  // 2 pi * 2^28
  const int64_t kappa_u = muldiv_round(dz_u, static_cast<int64_t>(1) << 60, kTwoPiQ28 * span);
  const int64_t r2 = t.r2_u, reach2 = sweep_reach2(t);
  constexpr int64_t kQ30 = static_cast<int64_t>(1) << 30;
  // Columns within R of the circle (rho = floor(|q|), the test below).
  const PieceBox box = piece_box(ax, ay, bx, by, ra, radius_of(ax, ay), dir);
  const ArcRing ring{max_of<int64_t>(0, ra - t.r_u - 1), ra + t.r_u + 1};
  cut_arc_box(g, t, tune, st, cx_nm, cy_nm, box.x0, box.y0, box.x1, box.y1, ring, zlow, zhigh,
              [&](int64_t qx, int64_t qy, int64_t, int64_t* h_v, int64_t* zct_v) {
    const int64_t rho2 = qx * qx + qy * qy;
    const int64_t rho = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(rho2)));
    if (rho - ra > t.r_u || ra - rho > t.r_u) return ArcColumn::kOut;  // never within R of the circle
    // The window of reach, [lo, hi] in bam along the piece.
    const int64_t s_p = dir * static_cast<int64_t>(static_cast<int32_t>(atan2_bam(qy, qx) - phi_a));
    int64_t alpha = static_cast<int64_t>(1) << 31;
    if (rho > 0) {
      const int64_t c_q30 = muldiv_round(rho2 + ra * ra - r2, kQ30, 2 * rho * ra);
      if (c_q30 > kQ30) return ArcColumn::kOut;
      if (c_q30 > -kQ30) {
        const int64_t sn = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(kQ30 * kQ30 - c_q30 * c_q30)));
        alpha = atan2_bam(sn, c_q30);
      }
    } else if (ra > t.r_u) {
      return ArcColumn::kOut;
    }
    const int64_t lo = max_of<int64_t>(0, s_p - alpha), hi = min_of(span, s_p + alpha);
    if (lo > hi) return ArcColumn::kOut;
    int64_t s_best;
    if (t.kind == ToolKind::kFlat || rho == 0) {
      s_best = dz_v < 0 ? hi : lo;
    } else {
      // kk and qq in q30 (the arc qualified with kk < 2^16 for every rho).
      const int64_t kk = muldiv_round(muldiv_round(kappa_u, kQ30, rho), kappa_u, ra);
      const int64_t qq = muldiv_round(r2 - rho2 - ra * ra, kQ30, rho * ra);
      // kk < 2^16 (q30: 2^46, the arc's qualification), so kk^2 < 2^62 (q30);
      // kk qq saturates where a column hugs the axis of a helix just wider
      // than the tool (qq ~ ra / rho): saturated sums (a root past the
      // clamp below either way).
      const int64_t disc = sat_add_i64(sat_sub_i64(mul_shift(kk, kk, 30), mul_shift(kk, qq, 30)), kQ30);
      const int64_t root = disc > 0 ? static_cast<int64_t>(isqrt_u128(shl_u128(U128{0, static_cast<uint64_t>(disc)}, 30))) : 0;
      const int64_t c = clamp(root - kk, -kQ30, kQ30);
      const int64_t sn = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(kQ30 * kQ30 - c * c)));
      const int64_t u = static_cast<int64_t>(atan2_bam(sn, c));
      s_best = clamp(s_p + (dz_v > 0 ? -u : u), lo, hi);
    }
    if (s_best == 0 && !start_cap) return ArcColumn::kOut;  // the tool at A: cut by the move before
    // r^2 at s_best = (rho - ra)^2 + 4 rho ra sin^2((s - s_P) / 2).
    const SinCosQ30 half = sincos_bam(static_cast<uint32_t>((s_best - s_p) / 2));
    const int64_t t1 = mul_shift(rho, half.sin_q30, 30), t2 = mul_shift(ra, half.sin_q30, 30);
    const int64_t d2 = (rho - ra) * (rho - ra) + 4 * t1 * t2;
    if (d2 > reach2) return ArcColumn::kOut;
    *h_v = z0_v + muldiv_round(dz_v, s_best, span) + sweep_profile_v(t, min_of(d2, t.r2_u));
    // The highest position covering the column: the window's other end.
    if (zct_v) *zct_v = z0_v + muldiv_round(dz_v, dz_v > 0 ? hi : lo, span);
    return ArcColumn::kCut;
  });
}

}  // namespace

// A helix of several turns about Z (G2/G3 with P in G17) sweeps the same XY
// path every turn, each turn lower (or higher) than the one before: every
// position of a descending helix has its twin one turn later, at the same XY
// and lower, so the last full turn alone cuts everything the whole helix
// cuts; an ascending helix's first turn, a level one's any turn. The one
// turn that does, into *one; false when the arc has at most one turn
// (cutting every turn, a 10 000-turn helix cost 10 000 turns).
bool dominant_turn(const CanonRecord& arc, bool* start_cap, CanonRecord* one) {
  if (arc.arc.plane != Plane::kXY || (arc.arc.turns >= -1 && arc.arc.turns <= 1)) return false;
  const int dir = arc.arc.turns < 0 ? -1 : 1;
  const int64_t cx = arc.arc.centre.x_nm, cy = arc.arc.centre.y_nm;
  const uint32_t phi_a = atan2_bam(arc.start.y_nm - cy, arc.start.x_nm - cx);
  const uint32_t phi_b = atan2_bam(arc.end.y_nm - cy, arc.end.x_nm - cx);
  uint64_t last = static_cast<uint32_t>(dir > 0 ? phi_b - phi_a : phi_a - phi_b);  // the span past the full turns
  const bool same_xy = arc.start.x_nm == arc.end.x_nm && arc.start.y_nm == arc.end.y_nm;
  if (same_xy || last == 0) last = static_cast<uint64_t>(1) << 32;
  const uint64_t extra = static_cast<uint64_t>(dir * arc.arc.turns - 1);
  const uint64_t total_bam = extra * (static_cast<uint64_t>(1) << 32) + last;  // < 2^63 for |turns| < 2^31
  const int64_t dz = arc.end.z_nm - arc.start.z_nm;
  // One turn's share of the descent (a full turn is 2^32 of total_bam).
  const int64_t turn_dz = muldiv_round(dz, static_cast<int64_t>(1) << 32, static_cast<int64_t>(total_bam));
  *one = arc;
  one->arc.turns = dir;
  if (dz < 0) {  // the last turn: from B's place one turn back, down to B
    one->start = PointNm{arc.end.x_nm, arc.end.y_nm, arc.end.z_nm - turn_dz};
    *start_cap = true;  // it starts mid-path: its first position is the path's own
  } else {         // the first turn (and, level, any turn): from A round to A
    one->end = PointNm{arc.start.x_nm, arc.start.y_nm, arc.start.z_nm + turn_dz};
  }
  return true;
}

bool sweep_arc_exact(const SweepTool& t, const CanonRecord& arc) {
  const bool exact_shape = t.kind == ToolKind::kBall || t.kind == ToolKind::kFlat;
  const int64_t cx = arc.arc.centre.x_nm, cy = arc.arc.centre.y_nm;
  const int64_t ra_nm = hypot_round(arc.start.x_nm - cx, arc.start.y_nm - cy);
  const bool exact = exact_shape && arc.arc.plane == Plane::kXY && ra_nm > 0 && ra_nm <= kMaxExactRadiusNm;
  if (!exact || arc.start.z_nm == arc.end.z_nm) return exact;
  // The helix formulas want ra > R (a window under half a turn; for the
  // ball, convex) and kk < 2^16 at the closest column, rho = ra - R:
  // kappa^2 < 2^16 ra (ra - R), kappa the descent per radian (bounded by
  // dz over the whole sweep / 1 rad). Helices tighter than the tool (a
  // helical bore) go through chords.
  const int64_t ra_u = ra_nm * kSweepUnitsPerNm;
  const uint64_t dz_u = abs_u64(arc.end.z_nm - arc.start.z_nm) * kSweepUnitsPerNm;
  return ra_u > t.r_u && static_cast<uint64_t>(mul_shift(static_cast<int64_t>(dz_u), static_cast<int64_t>(dz_u), 16)) <
                             static_cast<uint64_t>(ra_u) * static_cast<uint64_t>(ra_u - t.r_u);
}

// fn(a, b) for each chord of the arc near the grid (core/cut/arc_walk.h).
template <class H, class Fn>
void each_chord(const DexelGrid<H>& g, const SweepTool& t, const CanonRecord& arc, Fn fn) {
  const int64_t margin = 2 * (t.r_u / kSweepUnitsPerNm) + g.pitch_nm;
  const RectNm reach{g.x0_nm - margin, g.y0_nm - margin, g.x0_nm + (g.nx - 1) * g.pitch_nm + margin,
                     g.y0_nm + (g.ny - 1) * g.pitch_nm + margin};
  arc_walk(arc, kArcChordSagittaNm, reach, fn);
}

template <class H, int W>
void sweep_arc_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, const CanonRecord& arc, CutStats* st,
                 bool start_cap) {
  CanonRecord one;
  if (dominant_turn(arc, &start_cap, &one)) {
    sweep_arc_w<H, W>(g, t, tune, one, st, start_cap);
    return;
  }
  if (!sweep_arc_exact(t, arc)) {
    // Each chord with both caps; a joint is chained when the chord starts
    // where the last one ended.
    PointNm last = arc.start;
    bool chained = !start_cap;
    each_chord(*g, t, arc, [&](PointNm a, PointNm b) {
      sweep_line_w<H, W>(g, t, tune, a, b, st, !(chained && a == last));
      last = b;
      chained = true;
    });
    return;
  }
  const int64_t cx = arc.arc.centre.x_nm, cy = arc.arc.centre.y_nm;
  const int64_t ra_nm = hypot_round(arc.start.x_nm - cx, arc.start.y_nm - cy);
  const bool level = arc.start.z_nm == arc.end.z_nm;
  ArcChords pieces;
  // Quarter-turn pieces: a sagitta as large as the radius.
  pieces.init(arc, ra_nm);
  PointNm from = arc.start, to;
  bool cap = start_cap;
  while (pieces.next(&to)) {
    {
      // The piece on the circle of the start's radius; the end's radius may
      // differ by the interpreter's tolerance: that gap is a straight sweep.
      const int64_t ax = (from.x_nm - cx) * kSweepUnitsPerNm, ay = (from.y_nm - cy) * kSweepUnitsPerNm;
      const int64_t ex = to.x_nm - cx, ey = to.y_nm - cy;
      const int64_t re = hypot_round(ex, ey);
      const int64_t bx_nm = re ? muldiv_round(ex, ra_nm, re) : 0, by_nm = re ? muldiv_round(ey, ra_nm, re) : 0;
      if (level)
        level_piece(g, t, tune, cx, cy, ax, ay, bx_nm * kSweepUnitsPerNm, by_nm * kSweepUnitsPerNm,
                    ra_nm * kSweepUnitsPerNm, arc.arc.turns < 0 ? -1 : 1, from.z_nm, st, cap);
      else
        helix_piece(g, t, tune, cx, cy, ax, ay, bx_nm * kSweepUnitsPerNm, by_nm * kSweepUnitsPerNm,
                    ra_nm * kSweepUnitsPerNm, arc.arc.turns < 0 ? -1 : 1, from.z_nm, to.z_nm, st, cap);
      const PointNm on_circle{cx + bx_nm, cy + by_nm, to.z_nm};
      if (!(on_circle == to)) sweep_line_w<H, W>(g, t, tune, on_circle, to, st, false);
    }
    from = to;
    cap = false;
  }
}

template <class H, int W>
void sweep_chain_arc_w(DexelGrid<H>* g, const SweepTool& t, const SweepTuning& tune, const CanonRecord& arc,
                       CutStats* st, SweepChain* c) {
  CanonRecord one;
  bool mid_path = false;
  const CanonRecord& turn = dominant_turn(arc, &mid_path, &one) ? one : arc;
  if (!sweep_arc_exact(t, turn)) {
    // Chords go on the chain as the straight moves they are: each cuts its
    // band and only the wedge of its start cap the chord before leaves
    // (SweepChain, core/cut/sweep.h), instead of a whole cap a chord (the
    // arcs of an XZ profile with a ball: 40 % of the dexel updates of
    // blur_torus.ngc, tools/README.md). A turn that starts mid-path does not
    // start at the chain's end, which then ends first.
    each_chord(*g, t, turn, [&](PointNm a, PointNm b) { sweep_chain_line_w<H, W>(g, t, tune, a, b, st, c); });
    if (!(c->end == arc.end)) {  // chords off the grid, or the first turn of a rising helix
      sweep_chain_end_w<H, W>(g, t, tune, st, c);
      c->state = SweepChain::State::kCovered;
      c->end = arc.end;
    }
    return;
  }
  sweep_chain_end_w<H, W>(g, t, tune, st, c);
  const bool joined = c->state != SweepChain::State::kFresh && c->end == arc.start;
  sweep_arc_w<H, W>(g, t, tune, arc, st, !joined);
  c->state = SweepChain::State::kCovered;
  c->end = arc.end;
}

template <class H>
void sweep_arc(DexelGrid<H>* g, const SweepTool& t, const CanonRecord& arc, CutStats* st, bool start_cap) {
  sweep_arc_w<H, kSweepWordBits>(g, t, kSweepDefaults, arc, st, start_cap);
}

template <class H>
void sweep_chain_arc(DexelGrid<H>* g, const SweepTool& t, const CanonRecord& arc, CutStats* st, SweepChain* c) {
  sweep_chain_arc_w<H, kSweepWordBits>(g, t, kSweepDefaults, arc, st, c);
}

#define DEXMILL_SWEEP_ARC_W_INSTANTIATE(H, W)                                                                   \
  template void sweep_arc_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, const CanonRecord&,     \
                                  CutStats*, bool);                                                            \
  template void sweep_chain_arc_w<H, W>(DexelGrid<H>*, const SweepTool&, const SweepTuning&, const CanonRecord&, \
                                        CutStats*, SweepChain*);
#define DEXMILL_SWEEP_ARC_INSTANTIATE(H)                                                                    \
  DEXMILL_SWEEP_ARC_W_INSTANTIATE(H, 32)                                                                    \
  DEXMILL_SWEEP_ARC_W_INSTANTIATE(H, 64)                                                                    \
  template void sweep_arc<H>(DexelGrid<H>*, const SweepTool&, const CanonRecord&, CutStats*, bool);         \
  template void sweep_chain_arc<H>(DexelGrid<H>*, const SweepTool&, const CanonRecord&, CutStats*, SweepChain*);
DEXMILL_SWEEP_ARC_INSTANTIATE(uint8_t)
DEXMILL_SWEEP_ARC_INSTANTIATE(uint16_t)
DEXMILL_SWEEP_ARC_INSTANTIATE(uint32_t)

}  // namespace dexmill
