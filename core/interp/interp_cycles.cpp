// The interpreter's canned cycles (LinuxCNC's interp_cycles.cc, convert_cycle
// and convert_cycle_xy/yz/zx): the block's words and the sticky ones, the
// levels, the spindle each cycle needs, the range checks; the moves come
// from cycles.h when the block commits.
#include "core/canon/arc_chords.h"
#include "core/interp/block_runner.h"

namespace dexmill {

namespace {

bool needs_dwell(int motion) { return motion == 820 || motion == 860 || motion == 880 || motion == 890; }
bool pecks(int motion) { return motion == 730 || motion == 830; }

}  // namespace

// R, the bottom (the plane's axis word), L, Q, P and G87's I/J/K, each from
// the block or kept from the last block of the same cycle (RS274/NGC: they
// are sticky while the cycle repeats; LinuxCNC keeps P even across cycles).
GcodeError BlockRunner::cycle_words(int motion, const char* w, CycleWords* out) {
  GcodeError e;
  const uint16_t col = motion_col();
  const bool same = cur.motion == motion;
  const char lc = kAxisLetter[plane_axis_c(nx.plane)];
  out->r_raw = cur.cycle_r_nm;
  out->z_raw = cur.cycle_z_nm;
  if (b.has_word('R')) {
    if ((e = length('R', &out->r_raw)) != GcodeError::kOk) return e;
  } else if (!same) {
    return fail(GcodeError::kCycleNoR, col, w);
  }
  if (b.has_word(lc)) {
    if ((e = length(lc, &out->z_raw)) != GcodeError::kOk) return e;
  } else if (!same) {
    return fail(GcodeError::kCycleNoZ, col, w);
  }
  out->repeats = 1;
  if (b.has_word('L')) {
    if ((e = integer('L', 0, kMaxRepeats, &out->repeats)) != GcodeError::kOk) return e;
    if (out->repeats == 0) return fail_letter(GcodeError::kCycleZeroRepeats, 'L');
  }
  out->q = cur.cycle_q_nm;
  if (pecks(motion)) {
    if (b.has_word('Q')) {
      if ((e = length('Q', &out->q)) != GcodeError::kOk) return e;
    } else if (!same) {
      return fail(GcodeError::kCycleNoQ, col, w);
    }
    if (out->q <= 0) return b.has_word('Q') ? fail_letter(GcodeError::kCycleQNotPositive, 'Q')
                                            : fail(GcodeError::kCycleQNotPositive, col, w);
  }
  // P: G82/G86/G88/G89 need one when the cycle starts; G74/G84 take the
  // last one given (0 at first).
  out->p_ms = cur.cycle_p_ms;
  if (b.has_word('P') && (needs_dwell(motion) || motion == 740 || motion == 840)) {
    const Decimal& pv = b.val('P');
    if (decimal_is_negative(pv)) return fail_letter(GcodeError::kNegativeValue, 'P');
    out->p_ms = decimal_scale(pv, 1000);
    if (out->p_ms > kMaxDwellS * 1000) return fail_letter(GcodeError::kNumberTooLarge, 'P');
  } else if (needs_dwell(motion) && !same) {
    return fail(GcodeError::kCycleNoP, col, w);
  }
  for (int ax = 0; ax < 3; ++ax) out->ijk[ax] = cur.cycle_ijk_nm[ax];
  if (motion == 870) {
    const char ijk[3] = {'I', 'J', 'K'};
    for (int ax = 0; ax < 3; ++ax) {
      if (b.has_word(ijk[ax])) {
        if ((e = length(ijk[ax], &out->ijk[ax])) != GcodeError::kOk) return e;
      } else if (!same) {
        return fail(GcodeError::kCycleNoIjk, col, w);
      }
    }
  }
  return GcodeError::kOk;
}

// The spindle a cycle needs (convert_cycle_g74_g84, _g86, _g87, _g88):
// tapping one way, boring either way.
GcodeError BlockRunner::cycle_spindle(int motion, const char* w) {
  const bool taps = motion == 740 || motion == 840;
  if (!taps && motion != 860 && motion != 870 && motion != 880) return GcodeError::kOk;
  if (nx.spindle_dir == 0) return fail(GcodeError::kCycleSpindleStopped, motion_col(), w);
  if (taps && nx.spindle_dir != (motion == 840 ? 1 : -1)) return fail(GcodeError::kCycleSpindleWrongWay, motion_col(), w);
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_cycle(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  if (nx.inverse_time) return fail(GcodeError::kCycleInverseTime, col, w);
  if ((e = need_feed(col, w)) != GcodeError::kOk) return e;
  CycleWords cw;
  if ((e = cycle_words(motion, w, &cw)) != GcodeError::kOk) return e;
  const Plane pl = nx.plane;
  const int ia = plane_axis_a(pl), ib = plane_axis_b(pl), ic = plane_axis_c(pl);
  CyclePlan& c = plan.cycle;
  c.code = static_cast<int16_t>(motion);
  c.plane = pl;
  c.repeats = cw.repeats;
  c.q_nm = cw.q;
  c.dwell_ms = cw.p_ms;
  c.spindle_rpm = nx.spindle_dir * nx.spindle_rpm;
  c.start_a = axis_val(cur.pos, ia);
  c.start_b = axis_val(cur.pos, ib);
  const int64_t cur_c = axis_val(cur.pos, ic);
  // LinuxCNC's cycle_il: the level when the series began, kept in program
  // coordinates, so a G92 or G10 between the blocks of a series moves it
  // with the offsets (G0 Z10, G81 ... R1, G92 Z5: G98 then returns to Z15).
  int64_t old_c = cur.cycle_level_set ? cur.cycle_level_nm + offset(ic) : cur_c;
  nx.cycle_level_set = true;
  nx.cycle_level_nm = old_c - offset(ic);
  nx.cycle_level_path_nm = old_c;
  int64_t va = 0, vb = 0;
  const char la = kAxisLetter[ia], lb = kAxisLetter[ib];
  if (b.has_word(la) && (e = length(la, &va)) != GcodeError::kOk) return e;
  if (b.has_word(lb) && (e = length(lb, &vb)) != GcodeError::kOk) return e;
  // G87's offset: I, J, K of the plane's axes, always increments; its top
  // is the word of the plane's axis, absolute, or (G91) from the bottom.
  c.off_a = cw.ijk[ia];
  c.off_b = cw.ijk[ib];
  if (nx.incremental) {
    // RS274/NGC: X, Y and R are increments from the current point and the
    // initial level, Z an increment from R.
    c.inc_a = va;
    c.inc_b = vb;
    c.a = c.start_a;
    c.b = c.start_b;
    c.r_c = cw.r_raw + old_c;
    c.bottom_c = c.r_c + cw.z_raw;
    c.middle_c = c.bottom_c + cw.ijk[ic];
  } else {
    c.inc_a = c.inc_b = 0;
    c.a = b.has_word(la) ? va + offset(ia) : c.start_a;
    c.b = b.has_word(lb) ? vb + offset(ib) : c.start_b;
    c.r_c = cw.r_raw + offset(ic);
    c.bottom_c = cw.z_raw + offset(ic);
    c.middle_c = cw.ijk[ic] + offset(ic);
  }
  if (c.r_c < c.bottom_c) {
    d->a_nm = c.r_c;
    d->b_nm = c.bottom_c;
    return fail(GcodeError::kCycleRBelowZ, col, w);
  }
  if ((e = cycle_spindle(motion, w)) != GcodeError::kOk) return e;
  c.current_c = cur_c;
  c.raise_first = old_c < c.r_c;
  if (c.raise_first) {
    old_c = c.r_c;
    c.current_c = c.r_c;
  }
  c.clear_c = nx.retract_to_r ? c.r_c : old_c;
  c.polar = false;
  if (b.has_polar() && (e = cycle_polar(w)) != GcodeError::kOk) return e;
  if ((e = cycle_check_range(w)) != GcodeError::kOk) return e;
  if (pecks(motion)) {
    const int64_t n = cycle_peck_count(c.r_c, c.bottom_c, cw.q);
    if (n > kMaxCyclePecks / cw.repeats) {
      d->a_nm = n > INT64_MAX / cw.repeats ? INT64_MAX : n * cw.repeats;
      d->b_nm = c.r_c - c.bottom_c;
      return fail(GcodeError::kCyclePeckCount, b.has_word('Q') ? b.col_of('Q') : col, w);
    }
  }
  cycle_warnings(motion, w);
  nx.cycle_r_nm = cw.r_raw;
  nx.cycle_z_nm = cw.z_raw;
  nx.cycle_q_nm = cw.q;
  nx.cycle_p_ms = cw.p_ms;
  for (int ax = 0; ax < 3; ++ax) nx.cycle_ijk_nm[ax] = cw.ijk[ax];
  plan.motion = Plan::kCycle;
  int64_t last_a, last_b;
  cycle_last_hole(c, &last_a, &last_b);
  nx.pos = plane_point(pl, last_a, last_b, c.clear_c);
  const PointNm end = cycle_last_point(c);
  nx.stray = PointNm{end.x_nm - nx.pos.x_nm, end.y_nm - nx.pos.y_nm, end.z_nm - nx.pos.z_nm};
  return GcodeError::kOk;
}

// Range: the holes lie on a line, so its ends bound them; levels likewise.
GcodeError BlockRunner::cycle_check_range(const char* w) {
  GcodeError e;
  const CyclePlan& c = plan.cycle;
  const int64_t ends_a[2] = {c.a + c.inc_a, c.a + c.inc_a * c.repeats};
  const int64_t ends_b[2] = {c.b + c.inc_b, c.b + c.inc_b * c.repeats};
  const int64_t levels[5] = {c.r_c, c.bottom_c, c.clear_c, c.current_c, c.code == 870 ? c.middle_c : c.r_c};
  for (int k = 0; k < 2; ++k) {
    for (int64_t lv : levels) {
      if ((e = check_pos(plane_point(c.plane, ends_a[k], ends_b[k], lv), motion_col(), w)) != GcodeError::kOk) return e;
      if (c.code == 870 &&
          (e = check_pos(plane_point(c.plane, ends_a[k] + c.off_a, ends_b[k] + c.off_b, lv), motion_col(), w)) !=
              GcodeError::kOk)
        return e;
    }
  }
  return GcodeError::kOk;
}

// What LinuxCNC does here that a user may not expect: said once, or when
// it happens.
void BlockRunner::cycle_warnings(int motion, const char* w) {
  const CyclePlan& c = plan.cycle;
  const uint16_t col = motion_col();
  if (cur.cycle_level_set && c.clear_c == nx.cycle_level_path_nm && nx.cycle_level_path_nm != cur.cycle_level_path_nm)
    in.warn(GcodeError::kWarnCycleLevelMoved, b.line, col, w, nx.cycle_level_path_nm, cur.cycle_level_path_nm);
  if ((motion == 740 || motion == 840) && c.plane != Plane::kXY)
    warn_once(kOnceTapPlane, GcodeError::kWarnTapPlane, col, w);
  if (motion == 880) warn_once(kOnceManualRetract, GcodeError::kWarnManualRetract, col, w);
}

}  // namespace dexmill
