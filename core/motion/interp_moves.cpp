// The interpreter's moves: G0/G1 (with G53), G2/G3 in either format (the
// checks of arc_center.h), and the canned cycles G73/G81-G83/G85/G89 (their
// moves from cycles.h), each checked against the range limits before the
// block commits.
#include "core/motion/arc_center.h"
#include "core/motion/arc_chords.h"
#include "core/motion/block_runner.h"

namespace dexmill {

GcodeError BlockRunner::run_motion(int motion) {
  if (motion != cur.motion) {
    nx.motion = static_cast<int16_t>(motion);
    if (!is_cycle(motion)) nx.cycle_level_set = false;
  }
  if (motion == 800) return GcodeError::kOk;
  // G0/G1 written with no axis word make a move of length zero (LinuxCNC
  // emits it, and checks the feed of G1); a modal one on a line of other
  // words (F100 alone) makes none.
  if (!b.has_axis() && (motion == 0 || motion == 10) && b.g[kGMotion] < 0) return GcodeError::kOk;
  if (motion == 0 || motion == 10) return run_straight(motion, b.g[kGNonModal] == 530);
  if (motion == 20 || motion == 30) return run_arc(motion);
  if (!b.has_axis() && b.g[kGMotion] < 0) return GcodeError::kOk;
  return run_cycle(motion);
}

GcodeError BlockRunner::run_straight(int motion, bool g53) {
  GcodeError e;
  if (g53 && nx.incremental) return fail_code(GcodeError::kG53Incremental, 'G', 530, b.g_col[kGNonModal]);
  PointNm to = cur.pos;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    if (g53) axis_ref(to, ax) = v - (ax == 2 ? nx.tlo_nm : 0);
    else axis_ref(to, ax) = nx.incremental ? axis_val(cur.pos, ax) + v : v + offset(ax);
  }
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  if ((e = check_pos(to, motion_col(), w)) != GcodeError::kOk) return e;
  if (motion == 10) {
    if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, motion_col(), w);
    if (!nx.inverse_time && nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, motion_col(), w);
    if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  }
  plan.motion = Plan::kStraight;
  plan.straight_kind = motion == 0 ? CanonKind::kTraverse : CanonKind::kFeed;
  plan.target = to;
  plan.inverse_time = nx.inverse_time && motion == 10;
  nx.pos = to;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_arc(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  const Plane pl = nx.plane;
  const int ia = plane_axis_a(pl), ib = plane_axis_b(pl);
  // I, J, K belong to X, Y, Z; the one along the plane's axis is an error.
  const char off_letter[3] = {'I', 'J', 'K'};
  const char not_here = off_letter[plane_axis_c(pl)];
  if (b.has_word(not_here)) return fail_letter(GcodeError::kArcWordWrongPlane, not_here);
  const bool has_r = b.has_word('R');
  const bool has_ijk = b.has_word(off_letter[ia]) || b.has_word(off_letter[ib]);
  if (!has_r && !has_ijk) return fail(GcodeError::kArcNoCentre, col, w);
  if (has_r && has_ijk) return fail_letter(GcodeError::kArcRAndIjk, 'R');
  PointNm to = cur.pos;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    axis_ref(to, ax) = nx.incremental ? axis_val(cur.pos, ax) + v : v + offset(ax);
  }
  if ((e = check_pos(to, col, w)) != GcodeError::kOk) return e;
  int64_t turns = 1;
  if (b.has_word('P')) {
    if (!decimal_to_int(b.val('P'), &turns) || turns < 1) return fail_letter(GcodeError::kTurnsNotPositive, 'P');
    if (turns > kMaxTurns) return fail_letter(GcodeError::kNumberTooLarge, 'P');
  }
  if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, col, w);
  if (!nx.inverse_time && nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, col, w);
  if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  const ArcPlanar p{axis_val(cur.pos, ia), axis_val(cur.pos, ib), axis_val(to, ia), axis_val(to, ib)};
  int64_t ca, cb;
  if (has_r) {
    int64_t r;
    if ((e = length('R', &r, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    e = arc_centre_from_radius(p, r, motion == 20, &ca, &cb, &d->a_nm, &d->b_nm);
    if (e != GcodeError::kOk) return fail(e, b.g[kGMotion] >= 0 ? col : b.col_of('R'), w);
  } else {
    int64_t oa = 0, ob = 0;
    if (b.has_word(off_letter[ia]) && (e = length(off_letter[ia], &oa, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    if (b.has_word(off_letter[ib]) && (e = length(off_letter[ib], &ob, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    ca = nx.arc_absolute ? oa + offset(ia) : p.sa + oa;
    cb = nx.arc_absolute ? ob + offset(ib) : p.sb + ob;
    if (abs64(ca) > kGcodeMaxArcNm || abs64(cb) > kGcodeMaxArcNm) {
      d->a_nm = abs64(ca) > abs64(cb) ? ca : cb;
      return fail(GcodeError::kPositionOutOfRange, col, w);
    }
    e = arc_check_centre(p, ca, cb, nx.inch, &d->a_nm, &d->b_nm);
    if (e != GcodeError::kOk) {
      const uint16_t c = b.g[kGMotion] >= 0 ? col : b.col_of(b.has_word(off_letter[ia]) ? off_letter[ia] : off_letter[ib]);
      if (e == GcodeError::kArcZeroRadius) d->a_nm = d->a_nm < d->b_nm ? d->a_nm : d->b_nm;
      return fail(e, c, w);
    }
  }
  const int64_t sc = axis_val(cur.pos, plane_axis_c(pl));
  plan.motion = Plan::kArc;
  plan.target = to;
  plan.arc.plane = pl;
  plan.arc.centre = plane_point(pl, ca, cb, sc);
  plan.arc.turns = static_cast<int32_t>(motion == 20 ? -turns : turns);
  plan.inverse_time = nx.inverse_time;
  nx.pos = to;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_cycle(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  if (nx.inverse_time) return fail(GcodeError::kCycleInverseTime, col, w);
  if (nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, col, w);
  const bool same = cur.motion == motion;
  const Plane pl = nx.plane;
  const int ia = plane_axis_a(pl), ib = plane_axis_b(pl), ic = plane_axis_c(pl);
  const char lc = kAxisLetter[ic];
  int64_t r_raw = cur.cycle_r_nm, z_raw = cur.cycle_z_nm;
  if (b.has_word('R')) {
    if ((e = length('R', &r_raw)) != GcodeError::kOk) return e;
  } else if (!same) {
    return fail(GcodeError::kCycleNoR, col, w);
  }
  if (b.has_word(lc)) {
    if ((e = length(lc, &z_raw)) != GcodeError::kOk) return e;
  } else if (!same) {
    return fail(GcodeError::kCycleNoZ, col, w);
  }
  int64_t repeats = 1;
  if (b.has_word('L')) {
    if ((e = integer('L', 0, kMaxRepeats, &repeats)) != GcodeError::kOk) return e;
    if (repeats == 0) return fail_letter(GcodeError::kCycleZeroRepeats, 'L');
  }
  int64_t q = cur.cycle_q_nm, p_ms = cur.cycle_p_ms;
  if (motion == 730 || motion == 830) {
    if (b.has_word('Q')) {
      if ((e = length('Q', &q)) != GcodeError::kOk) return e;
    } else if (!same) {
      return fail(GcodeError::kCycleNoQ, col, w);
    }
    if (q <= 0) return b.has_word('Q') ? fail_letter(GcodeError::kCycleQNotPositive, 'Q')
                                       : fail(GcodeError::kCycleQNotPositive, col, w);
  }
  if (motion == 820 || motion == 890) {
    if (b.has_word('P')) {
      const Decimal& pv = b.val('P');
      if (decimal_is_negative(pv)) return fail_letter(GcodeError::kNegativeValue, 'P');
      p_ms = decimal_scale(pv, 1000);
      if (p_ms > kMaxDwellS * 1000) return fail_letter(GcodeError::kNumberTooLarge, 'P');
    } else if (!same) {
      return fail(GcodeError::kCycleNoP, col, w);
    }
  }
  CyclePlan& c = plan.cycle;
  c.code = static_cast<int16_t>(motion);
  c.plane = pl;
  c.repeats = repeats;
  c.q_nm = q;
  c.dwell_ms = p_ms;
  c.start_a = axis_val(cur.pos, ia);
  c.start_b = axis_val(cur.pos, ib);
  const int64_t cur_c = axis_val(cur.pos, ic);
  int64_t old_c = cur.cycle_level_set ? cur.cycle_level_nm : cur_c;
  nx.cycle_level_set = true;
  nx.cycle_level_nm = old_c;
  int64_t va = 0, vb = 0;
  const char la = kAxisLetter[ia], lb = kAxisLetter[ib];
  if (b.has_word(la) && (e = length(la, &va)) != GcodeError::kOk) return e;
  if (b.has_word(lb) && (e = length(lb, &vb)) != GcodeError::kOk) return e;
  if (nx.incremental) {
    // RS274/NGC: X, Y and R are increments from the current point and the
    // initial level, Z an increment from R.
    c.inc_a = va;
    c.inc_b = vb;
    c.a = c.start_a;
    c.b = c.start_b;
    c.r_c = r_raw + old_c;
    c.bottom_c = c.r_c + z_raw;
  } else {
    c.inc_a = c.inc_b = 0;
    c.a = b.has_word(la) ? va + offset(ia) : c.start_a;
    c.b = b.has_word(lb) ? vb + offset(ib) : c.start_b;
    c.r_c = r_raw + offset(ic);
    c.bottom_c = z_raw + offset(ic);
  }
  if (c.r_c < c.bottom_c) {
    d->a_nm = c.r_c;
    d->b_nm = c.bottom_c;
    return fail(GcodeError::kCycleRBelowZ, col, w);
  }
  c.current_c = cur_c;
  c.raise_first = old_c < c.r_c;
  if (c.raise_first) {
    old_c = c.r_c;
    c.current_c = c.r_c;
  }
  c.clear_c = nx.retract_to_r ? c.r_c : old_c;
  // Range: the holes lie on a line, so its ends bound it; levels likewise.
  const int64_t last_a = c.a + c.inc_a * repeats, last_b = c.b + c.inc_b * repeats;
  const int64_t levels[4] = {c.r_c, c.bottom_c, c.clear_c, c.current_c};
  for (int64_t lv : levels) {
    if ((e = check_pos(plane_point(pl, last_a, last_b, lv), col, w)) != GcodeError::kOk) return e;
    if ((e = check_pos(plane_point(pl, c.a + c.inc_a, c.b + c.inc_b, lv), col, w)) != GcodeError::kOk) return e;
  }
  if (motion == 730 || motion == 830) {
    const int64_t pecks = cycle_peck_count(c.r_c, c.bottom_c, q);
    if (pecks > kMaxCycleMoves / repeats) return b.has_word('Q') ? fail_letter(GcodeError::kNumberTooLarge, 'Q')
                                                                 : fail(GcodeError::kNumberTooLarge, col, w);
  }
  nx.cycle_r_nm = r_raw;
  nx.cycle_z_nm = z_raw;
  nx.cycle_q_nm = q;
  nx.cycle_p_ms = p_ms;
  plan.motion = Plan::kCycle;
  nx.pos = plane_point(pl, last_a, last_b, c.clear_c);
  return GcodeError::kOk;
}

}  // namespace dexmill
