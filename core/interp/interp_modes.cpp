// The interpreter's modal steps: feed mode, F, S, T, M6/M61, spindle,
// coolant, G4, plane, tool length offset, coordinate system, path and
// distance modes (run_modes, in LinuxCNC's order of execution), and group 0:
// G10 L2/L20, G28/G30 (with run_home), G28.1/G30.1, G92 and its variants.
#include "core/interp/block_runner.h"

namespace dexmill {

GcodeError BlockRunner::run_modes() {
  GcodeError e;
  // Units first: every length of the block is in the units the block sets.
  if (b.g[kGUnits] >= 0) nx.inch = b.g[kGUnits] == 200;
  // G7/G8 before any X word is read: LinuxCNC halves X in the block that says G7.
  if (b.g[kGLathe] >= 0) {
    nx.diameter_x = b.g[kGLathe] == 70;
    if (nx.diameter_x && !cur.diameter_x) warn_once(kOnceDiameter, GcodeError::kWarnDiameterMode, b.g_col[kGLathe], "G7");
  }
  if (b.g[kGFeedMode] >= 0) {
    // LinuxCNC sets F to 0 on every G93, G94 or G95 (the block's own F comes after).
    nx.inverse_time = b.g[kGFeedMode] == 930;
    nx.per_rev = b.g[kGFeedMode] == 950;
    nx.feed_nm_per_min = 0;
  }
  if (b.has_word('F')) {
    const Decimal& f = b.val('F');
    if (decimal_is_negative(f)) return fail_letter(GcodeError::kNegativeValue, 'F');
    if (decimal_scale(f, 1) > kMaxFeedUnitsPerMin) return fail_letter(GcodeError::kNumberTooLarge, 'F');
    if (nx.inverse_time) {
      plan.inverse_f = f;
    } else {
      // RS274/NGC's order of execution sets F (step 3) before the length
      // units (step 12): a G94 F on the line that says G20 or G21 is read in
      // the units before the line, and LinuxCNC moves at that (its canon
      // converts F when it gets it and not at a later units change). grbl
      // reads the line's units (InterpOptions::feed_in_line_units). A G95
      // feed per revolution is read in the line's units, as before.
      const bool changes = nx.inch != cur.inch;
      const bool line_units = nx.per_rev || in.options_.feed_in_line_units;
      nx.feed_nm_per_min = decimal_to_nm(f, line_units ? nx.inch : cur.inch);
      if (changes && !line_units)
        warn_once(kOnceFeedBeforeUnits, GcodeError::kWarnFeedBeforeUnits, b.col_of('F'), "F", nx.feed_nm_per_min);
      if (!nx.per_rev && nx.feed_nm_per_min > kFastFeedNmPerMin) warn_once(kOnceFastFeed, GcodeError::kWarnFastFeed, b.col_of('F'), "F");
    }
  }
  if (b.has_word('S')) {
    const Decimal& s = b.val('S');
    if (decimal_is_negative(s)) return fail_letter(GcodeError::kNegativeValue, 'S');
    int64_t rpm = decimal_scale(s, 1);
    if (rpm > kMaxSpindleRpm) return fail_letter(GcodeError::kNumberTooLarge, 'S');
    if (rpm > kFastSpindleRpm) warn_once(kOnceFastSpindle, GcodeError::kWarnFastSpindle, b.col_of('S'), "S");
    nx.spindle_rpm = static_cast<int32_t>(rpm);
  }
  if (b.has_word('T')) {
    int64_t t;
    if ((e = integer('T', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
    nx.selected_tool = static_cast<int32_t>(t);
  }
  if (cur.comp.side && (e = comp_forbid_m()) != GcodeError::kOk) return e;
  if (b.m[kMToolChange] == 60) {
    nx.tool = nx.selected_tool;
    plan.tool_change = true;
  } else if (b.m[kMToolChange] == 610) {  // M61 Q: set the tool number without a change
    if (!b.has_word('Q')) return fail_code(GcodeError::kWordUnused, 'M', 610, b.m_col[kMToolChange]);
    int64_t t;
    if ((e = integer('Q', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
    nx.tool = nx.selected_tool = static_cast<int32_t>(t);
    plan.tool_change = true;
  }
  if (b.m[kMSpindle] >= 0 && b.m[kMSpindle] != 190)
    nx.spindle_dir = static_cast<int8_t>(b.m[kMSpindle] == 30 ? 1 : b.m[kMSpindle] == 40 ? -1 : 0);
  const int32_t old_rpm = cur.spindle_dir * cur.spindle_rpm, new_rpm = nx.spindle_dir * nx.spindle_rpm;
  plan.spindle = old_rpm != new_rpm;
  if (b.m[kMContext] >= 0) {
    if ((e = run_context(b.m[kMContext])) != GcodeError::kOk) return e;
    if (plan.rest_skipped) return GcodeError::kOk;
  }
  if (b.coolant_bits) {
    nx.coolant = (b.coolant_bits & 4) ? 0 : static_cast<uint8_t>(nx.coolant | (b.coolant_bits & 3));
    plan.coolant = true;
  }
  if (b.g[kGNonModal] == 40) {
    if (!b.has_word('P')) return fail_code(GcodeError::kDwellNoP, 'G', 40, b.g_col[kGNonModal]);
    const Decimal& p = b.val('P');
    if (decimal_is_negative(p)) return fail_letter(GcodeError::kNegativeValue, 'P');
    int64_t ms = decimal_scale(p, 1000);
    if (ms > kMaxDwellS * 1000) return fail_letter(GcodeError::kNumberTooLarge, 'P');
    plan.dwell = true;
    plan.dwell_ms = ms;
  }
  if (b.g[kGPlane] >= 0) {
    nx.plane = b.g[kGPlane] == 170 ? Plane::kXY : b.g[kGPlane] == 180 ? Plane::kZX : Plane::kYZ;
    if (cur.comp.side && nx.plane != cur.plane)
      return fail_code(GcodeError::kCompChangePlane, 'G', b.g[kGPlane], b.g_col[kGPlane]);
  }
  if ((b.g[kGCutterComp] >= 0 || cur.comp.side) &&
      ((e = comp_mode()) != GcodeError::kOk || (e = comp_forbid_modes()) != GcodeError::kOk))
    return e;
  if (b.g[kGToolLength] == 490) {
    nx.tlo_nm = 0;
  } else if (b.g[kGToolLength] == 430) {
    int64_t t = nx.tool;
    if (b.has_word('H')) {
      if ((e = integer('H', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
    }
    int64_t len = 0;
    if (in.options_.tools && t != 0 && !in.options_.tools->tool_length_nm(static_cast<int32_t>(t), &len))
      return b.has_word('H') ? fail_letter(GcodeError::kToolUnknown, 'H')
                             : fail_code(GcodeError::kToolUnknown, 'G', 430, b.g_col[kGToolLength]);
    if (abs64(len) > kGcodeMaxCoordNm) return fail_code(GcodeError::kNumberTooLarge, 'G', 430, b.g_col[kGToolLength]);
    nx.tlo_nm = len;
  } else if (b.g[kGToolLength] == 432) {
    // G43.2 (LinuxCNC 2.9): an offset added to the one in force, tool H's
    // length from the table, or the Z word; X/Y offsets are for lathes.
    const uint16_t col = b.g_col[kGToolLength];
    const bool axes = b.has_axis();
    if (b.has_word('H') && axes) return fail_code(GcodeError::kTloAddHAndAxes, 'G', 432, col);
    if (!b.has_word('H') && !axes) return fail_code(GcodeError::kTloAddNothing, 'G', 432, col);
    int64_t add = 0;
    if (b.has_word('H')) {
      int64_t t;
      if ((e = integer('H', 0, kMaxToolNumber, &t)) != GcodeError::kOk) return e;
      if (in.options_.tools && t != 0 && !in.options_.tools->tool_length_nm(static_cast<int32_t>(t), &add))
        return fail_letter(GcodeError::kToolUnknown, 'H');
    } else {
      if (b.has_word('X')) return fail_letter(GcodeError::kUnsupportedAxis, 'X');
      if (b.has_word('Y')) return fail_letter(GcodeError::kUnsupportedAxis, 'Y');
      if (b.has_word('Z') && (e = length('Z', &add)) != GcodeError::kOk) return e;
    }
    if (abs64(add) > kGcodeMaxCoordNm || abs64(cur.tlo_nm + add) > kGcodeMaxCoordNm)
      return fail_code(GcodeError::kNumberTooLarge, 'G', 432, col);
    nx.tlo_nm = cur.tlo_nm + add;
  } else if (b.g[kGToolLength] == 431) {
    // G43.1: the axis words are the offset; only Z is kept (X/Y offsets are
    // for lathes and are not carried by the canonical record).
    int64_t z = 0;
    if (b.has_word('X')) return fail_letter(GcodeError::kUnsupportedAxis, 'X');
    if (b.has_word('Y')) return fail_letter(GcodeError::kUnsupportedAxis, 'Y');
    if (b.has_word('Z') && (e = length('Z', &z)) != GcodeError::kOk) return e;
    nx.tlo_nm = z;
  }
  if (nx.tlo_nm != cur.tlo_nm) {
    // The spindle stays where it is, so the controlled point (the tool tip,
    // machine position minus the offset) moves by the change, as in LinuxCNC.
    nx.pos.z_nm = cur.pos.z_nm - (nx.tlo_nm - cur.tlo_nm);
    char w[16];
    gcode_code_text('G', b.g[kGToolLength], w);
    if ((e = check_pos(nx.pos, b.g_col[kGToolLength], w)) != GcodeError::kOk) return e;
  }
  if (b.g[kGCoordSystem] >= 0) {
    const int g = b.g[kGCoordSystem];
    nx.coord_system = static_cast<uint8_t>(g <= 590 ? (g - 540) / 10 : 6 + (g - 591));
  }
  if (b.g[kGPathControl] >= 0) {
    // G64 P in the block's units; a negative P counts as none (LinuxCNC
    // blends as fast as possible for P <= 0), one over 2.1 m as 2.1 m. Q, the naive-CAM tolerance,
    // only merges collinear moves there and is not kept.
    nx.path_mode = b.g[kGPathControl];
    const int64_t p_nm = nx.path_mode == 640 && b.has_word('P') ? decimal_to_nm(b.val('P'), nx.inch) : 0;
    nx.path_tolerance_nm = static_cast<int32_t>(clamp<int64_t>(p_nm, 0, INT32_MAX));
  }
  if (b.g[kGDistance] >= 0) nx.incremental = b.g[kGDistance] == 910;
  if (b.g[kGArcDistance] >= 0) nx.arc_absolute = b.g[kGArcDistance] == 901;
  if (b.g[kGRetract] >= 0) nx.retract_to_r = b.g[kGRetract] == 990;
  return GcodeError::kOk;
}

// M70-M73 at their place in LinuxCNC's order of execution: after F, S and
// the spindle, before coolant and the modes after it, so that a block's own
// G17-G19, G90/G91, G43 ... still apply after its M72. Units and G7/G8,
// which this reader takes first (every length of a block is read in the
// units it sets), are saved as they were before the block and put back on
// top of a restore.
GcodeError BlockRunner::run_context(int m) {
  if (m == 700 || m == 730) {
    InterpState s = nx;
    s.inch = cur.inch;
    s.diameter_x = cur.diameter_x;
    plan.context = modal_context_save(s, m == 730);
    plan.context_op = static_cast<int16_t>(m);
    return GcodeError::kOk;
  }
  if (m == 710) {
    plan.context_op = 710;
    return GcodeError::kOk;
  }
  const ModalContext& c = in.contexts_[in.context_level()];
  if (!c.valid) return fail_code(GcodeError::kContextNone, 'M', 720, b.m_col[kMContext]);
  if (c.comp_side != nx.comp.side) return fail_code(GcodeError::kUnsupportedContextComp, 'M', 720, b.m_col[kMContext]);
  // LinuxCNC 2.9 restores by running the modes that differ as a block of
  // their own (its gen_restore_cmd), which takes the place of this one: when
  // there is such a mode, the rest of the line (its coolant, modes, motion,
  // stop) is not run. Only the retract mode is set without it.
  InterpState saved = nx;
  modal_context_apply(c, &saved);
  saved.retract_to_r = nx.retract_to_r;
  const bool reissued = !(modal_context_save(saved, false) == modal_context_save(nx, false));
  modal_context_apply(c, &nx);
  if (!reissued) {
    if (b.g[kGUnits] >= 0) nx.inch = b.g[kGUnits] == 200;
    if (b.g[kGLathe] >= 0) nx.diameter_x = b.g[kGLathe] == 70;
  } else {
    plan.rest_skipped = true;
    if (context_rest_follows()) in.warn(GcodeError::kWarnContextRest, b.line, b.m_col[kMContext], "M72");
  }
  plan.spindle = cur.spindle_dir * cur.spindle_rpm != nx.spindle_dir * nx.spindle_rpm;
  plan.coolant = nx.coolant != cur.coolant;
  return GcodeError::kOk;
}

// Whether the block says anything LinuxCNC runs after M70-M73's place.
bool BlockRunner::context_rest_follows() const {
  if (b.has_axis() || b.coolant_bits || b.m[kMStop] >= 0) return true;
  for (int g = 0; g < kGGroupCount; ++g)
    if (g != kGFeedMode && b.g[g] >= 0) return true;
  return false;
}

GcodeError BlockRunner::run_group0(int g0) {
  GcodeError e;
  const uint16_t col = b.g_col[kGNonModal];
  if (nx.comp.side && (e = comp_forbid_group0(g0)) != GcodeError::kOk) return e;
  switch (g0) {
    case 100: {  // G10 L2 / L20: set a work offset
      if (!b.has_word('L')) return fail_code(GcodeError::kG10NoL, 'G', 100, col);
      int64_t l;
      if ((e = integer('L', 0, 100, &l)) != GcodeError::kOk) return e;
      if (l == 1 || l == 10 || l == 11) {
        char w[16];
        gcode_code_text('G', 100, w);
        in.warn(GcodeError::kWarnG10ToolTable, b.line, col, w);
        return GcodeError::kOk;
      }
      if (l != 2 && l != 20) return fail_letter(GcodeError::kG10BadL, 'L');
      if (!b.has_word('P')) return fail_code(GcodeError::kG10PNeeded, 'G', 100, col);
      int64_t p;
      if (!decimal_to_int(b.val('P'), &p) || p < 0 || p > 9) return fail_letter(GcodeError::kG10BadP, 'P');
      // LinuxCNC 2.9: R turns the system (L2 only); without R it keeps its turn.
      if (b.has_word('R') && l == 20) return fail_letter(GcodeError::kG10L20Rotation, 'R');
      const int sys = p == 0 ? nx.coord_system : static_cast<int>(p - 1);
      if (b.has_word('R')) {
        // Degrees e9 (to 1e-9 degree); at most a million turns either way.
        const int64_t r = decimal_scale(b.val('R'), 1000000000);
        if (abs64(r) > 360LL * 1000000 * 1000000000) return fail_letter(GcodeError::kNumberTooLarge, 'R');
        nx.rotation_deg_e9[sys] = r;
      }
      // L20: the offset that makes the tool's point read the given values in
      // that system (with a turn, X and Y both: o = m - rot(t + G92), t the
      // point read there, the given words put in).
      PointNm t{0, 0, 0};
      const PointNm m = machine_of(cur, cur.pos);
      if (l == 20) {
        InterpState there = nx;
        there.coord_system = static_cast<uint8_t>(sys);
        const PointNm q = frame_of_machine(there, m);
        t = PointNm{q.x_nm - nx.work_offset[sys].x_nm - nx.g92.x_nm, q.y_nm - nx.work_offset[sys].y_nm - nx.g92.y_nm,
                    q.z_nm - nx.work_offset[sys].z_nm - nx.g92.z_nm};
      }
      PointNm given = nx.work_offset[sys];
      for (int ax = 0; ax < 3; ++ax) {
        const char c = kAxisLetter[ax];
        if (!b.has_word(c)) continue;
        int64_t v;
        if ((e = length(c, &v)) != GcodeError::kOk) return e;
        axis_ref(l == 2 ? given : t, ax) = v;
      }
      if (l == 20) {
        const PointNm tg{t.x_nm + nx.g92.x_nm, t.y_nm + nx.g92.y_nm, t.z_nm + nx.g92.z_nm};
        const PointNm turned = rotate_about(xy_rotation(nx.rotation_deg_e9[sys]), tg, 0, 0);
        given = PointNm{m.x_nm - turned.x_nm, m.y_nm - turned.y_nm, m.z_nm - turned.z_nm};
      }
      for (int ax = 0; ax < 3; ++ax) {
        const int64_t off = axis_val(given, ax);
        if (abs64(off) > kGcodeMaxCoordNm) {
          d->a_nm = off;
          return fail_letter(GcodeError::kPositionOutOfRange, kAxisLetter[ax]);
        }
      }
      nx.work_offset[sys] = given;
      return GcodeError::kOk;
    }
    case 280:
    case 300:
      return run_home(g0);
    case 281:
    case 301: {  // the machine position (a turned frame's point turned)
      const PointNm m = machine_of(cur, cur.pos);
      (g0 == 281 ? nx.g28_home : nx.g30_home) = PointNm{m.x_nm, m.y_nm, m.z_nm + nx.tlo_nm};
      return GcodeError::kOk;
    }
    case 920: {  // G92: the current point reads the given values
      if (!b.has_axis()) return fail_code(GcodeError::kG92NoAxis, 'G', 920, col);
      for (int ax = 0; ax < 3; ++ax) {
        const char c = kAxisLetter[ax];
        if (!b.has_word(c)) continue;
        int64_t v;
        if ((e = length(c, &v)) != GcodeError::kOk) return e;
        int64_t off = axis_val(cur.pos, ax) - axis_val(nx.work_offset[nx.coord_system], ax) - v;
        if (abs64(off) > kGcodeMaxCoordNm) {
          d->a_nm = off;
          return fail_letter(GcodeError::kPositionOutOfRange, c);
        }
        axis_ref(nx.g92, ax) = off;
      }
      nx.g92_saved = nx.g92;
      return GcodeError::kOk;
    }
    case 921:
      nx.g92 = nx.g92_saved = PointNm{0, 0, 0};
      return GcodeError::kOk;
    case 922:
      nx.g92 = PointNm{0, 0, 0};
      return GcodeError::kOk;
    case 923:
      nx.g92 = nx.g92_saved;
      return GcodeError::kOk;
    default:
      return GcodeError::kOk;
  }
}

// G28/G30: rapid to the given point (if any axis is given), then rapid the
// given axes (all when none is given) to the stored machine position.
GcodeError BlockRunner::run_home(int g0) {
  GcodeError e;
  const PointNm home = g0 == 280 ? nx.g28_home : nx.g30_home;
  PointNm via = cur.pos, to = cur.pos;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    const int64_t home_path = axis_val(home, ax) - (ax == 2 ? nx.tlo_nm : 0);
    if (!b.has_axis()) {
      axis_ref(to, ax) = home_path;
      continue;
    }
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    axis_ref(via, ax) = nx.incremental ? axis_val(cur.pos, ax) + v : v + offset(ax);
    axis_ref(to, ax) = home_path;
  }
  if (rotated(nx)) {
    // LinuxCNC takes the stored position into the turned frame and moves
    // the given axes there (so a lone X goes along the turned X).
    const PointNm hf = frame_of_machine(nx, PointNm{home.x_nm, home.y_nm, home.z_nm - nx.tlo_nm});
    for (int ax = 0; ax < 3; ++ax)
      if (!b.has_axis() || b.has_word(kAxisLetter[ax])) axis_ref(to, ax) = axis_val(hf, ax);
  }
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(g0), w);
  if ((e = check_pos(via, b.g_col[kGNonModal], w)) != GcodeError::kOk) return e;
  if ((e = check_pos(to, b.g_col[kGNonModal], w)) != GcodeError::kOk) return e;
  plan.motion = Plan::kHome;
  plan.home_via = via;
  plan.target = to;
  nx.pos = to;
  return GcodeError::kOk;
}

}  // namespace dexmill
