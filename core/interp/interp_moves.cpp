// The interpreter's moves: G0/G1 (with G53), G2/G3 in either format (the
// checks of arc_center.h), the probe moves G38.2-G38.5 and the
// spindle-synchronised G33/G33.1, each checked
// against the range limits before the block commits (the canned cycles are
// in interp_cycles.cpp).
#include "core/interp/arc_center.h"
#include "core/canon/arc_chords.h"
#include "core/interp/block_runner.h"

namespace dexmill {

GcodeError BlockRunner::run_motion(int motion) {
  if (motion == 50 || motion == 51) {
    // LinuxCNC: "Cannot convert spline with cutter radius compensation".
    if (nx.comp.side) return fail_code(GcodeError::kCompForbidden, 'G', static_cast<int16_t>(motion), motion_col());
    return run_spline(motion);  // keeps the modal motion (interp_spline.cpp)
  }
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
  if (nx.comp.side) return fail_code(GcodeError::kCompForbidden, 'G', static_cast<int16_t>(motion), motion_col());
  if (is_probe(motion)) return run_probe(motion);
  if (motion == 330 || motion == 331) return run_sync(motion);
  if (motion == 52 || motion == 53) return run_nurbs(motion);
  return run_cycle(motion);
}

GcodeError BlockRunner::need_feed(uint16_t col, const char* word) {
  if (nx.per_rev) {  // G95: F per revolution, so S too (LinuxCNC's checks)
    if (nx.feed_nm_per_min == 0) return fail(GcodeError::kFeedZero, col, word);
    if (nx.spindle_rpm == 0) return fail(GcodeError::kFeedPerRevNoSpeed, col, word);
    return GcodeError::kOk;
  }
  if (nx.feed_nm_per_min != 0) return GcodeError::kOk;
  const int64_t standin = in.options_.default_feed_nm_per_min;
  if (standin <= 0) return fail(GcodeError::kFeedZero, col, word);
  // A controller's default feed (grbl and Fusion 360 programs count on one).
  nx.feed_nm_per_min = standin;
  warn_once(kOnceDefaultFeed, GcodeError::kWarnDefaultFeed, col, word, standin);
  return GcodeError::kOk;
}

// G38.2-G38.5 (LinuxCNC's convert_probe): a straight move at F towards the
// target, STRAIGHT_PROBE in its canonical output. The machine stops where
// the probe touches (or, G38.2/G38.4, fails when it does not) and LinuxCNC
// reads its position there; a preview cannot know where that is, so the
// move is simulated to its end point, with a warning.
GcodeError BlockRunner::run_probe(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  if (!b.has_axis()) return fail(GcodeError::kProbeNoAxis, col, w);
  // G93 leaves no F in force: LinuxCNC says "zero feed rate" too.
  if (nx.inverse_time) return fail(GcodeError::kFeedZero, col, w);
  if ((e = run_straight(motion, false)) != GcodeError::kOk) return e;
  if (plan.target == cur.pos) return fail(GcodeError::kProbeTooClose, col, w);
  ++in.probe_moves_;
  bool tripped = true;
  if (ProbeSensor* sensor = in.options_.probe) {
    // The stock says where the probe trips (G38.2/G38.3 on touching,
    // G38.4/G38.5 on leaving), as LinuxCNC's motion controller reports it.
    const PointNm at{cur.pos.x_nm + cur.stray.x_nm, cur.pos.y_nm + cur.stray.y_nm, cur.pos.z_nm + cur.stray.z_nm};
    PointNm stop{0, 0, 0};
    const ProbeSense r = sensor->sense(machine_of(cur, at), machine_of(nx, plan.target), motion, &stop);
    const bool toward = motion == 382 || motion == 383, must = motion == 382 || motion == 384;
    if (r == ProbeSense::kAlreadyTripped)
      return fail(toward ? GcodeError::kProbeAlreadyTripped : GcodeError::kProbeNotTripped, col, w);
    if (r == ProbeSense::kNoContact && must) return fail(GcodeError::kProbeNoContact, col, w);
    tripped = r == ProbeSense::kTripped;
    if (tripped) nx.pos = plan.target = frame_of_machine(nx, stop);  // the machine is where it stopped
  }
  // #5061-#5070: where the probe stopped, in the coordinates in force, and
  // whether it tripped (interp_params.cpp); without a sensor, the end point.
  for (int ax = 0; ax < 3; ++ax) axis_ref(nx.probe_prog, ax) = axis_val(plan.target, ax) - offset(ax);
  nx.probed = tripped;
  if (!in.options_.probe) warn_once(kOnceProbe, GcodeError::kWarnProbe, col, w);
  return GcodeError::kOk;
}

// G33 and G33.1 (LinuxCNC's convert_straight with its checks, in its
// order): K is the pitch, length per spindle revolution, so the feed is K
// times the spindle speed and the line may have no F. G33 is a straight
// feed to the target. G33.1 (RIGID_TAP) feeds to the target, reverses the
// spindle there and comes back along the same line to where it began, which
// is where LinuxCNC's position stays; the return is a second feed.
GcodeError BlockRunner::run_sync(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  if (b.has_word('F')) return fail(GcodeError::kSyncFeedWord, b.col_of('F'), w);
  if (!b.has_word('K')) return fail(GcodeError::kSyncNoPitch, col, w);
  if (!b.has_axis()) return fail(GcodeError::kSyncNoAxis, col, w);
  if (nx.spindle_dir == 0) return fail(GcodeError::kCycleSpindleStopped, col, w);
  int64_t pitch_nm;
  if ((e = length('K', &pitch_nm)) != GcodeError::kOk) return e;
  // LinuxCNC's interpreter passes K <= 0 on to a motion controller that then
  // never arrives (zero) or runs the spindle's way backwards: refused here.
  if (pitch_nm <= 0) return fail(GcodeError::kSyncPitchNotPositive, b.col_of('K'), w);
  const int64_t feed = sync_feed(pitch_nm, nx.spindle_rpm);
  if (feed == 0) return fail(GcodeError::kCycleSpindleStopped, col, w);  // S0: the spindle stands still
  if ((e = run_straight(motion, false)) != GcodeError::kOk) return e;  // the end point, checked
  if (feed > kFastFeedNmPerMin) warn_once(kOnceFastFeed, GcodeError::kWarnFastFeed, col, w);
  if (motion == 331) {
    plan.motion = Plan::kTap;
    nx.pos = cur.pos;  // G33.1 ends where it began
  }
  plan.inverse_time = false;
  plan.sync_feed_nm_per_min = feed;
  return GcodeError::kOk;
}

GcodeError BlockRunner::run_straight(int motion, bool g53) {
  GcodeError e;
  if (g53 && nx.incremental) return fail_code(GcodeError::kG53Incremental, 'G', 530, b.g_col[kGNonModal]);
  const PointNm base = g53 ? cur.pos : comp_base();
  PointNm to = base;
  for (int ax = 0; ax < 3; ++ax) {
    const char c = kAxisLetter[ax];
    if (!b.has_word(c)) continue;
    int64_t v;
    if ((e = length(c, &v)) != GcodeError::kOk) return e;
    if (g53) axis_ref(to, ax) = v - (ax == 2 ? nx.tlo_nm : 0);
    else axis_ref(to, ax) = nx.incremental ? axis_val(base, ax) + v : v + offset(ax);
  }
  if (b.has_polar() && g53) return fail_letter(GcodeError::kPolarG53, polar_letter());
  if (b.has_polar() && (e = polar_target(&to)) != GcodeError::kOk) return e;
  // G53's words are machine coordinates, as is the rest of its point then.
  if (g53 && rotated(nx)) {
    PointNm m = machine_of(nx, cur.pos);
    for (int ax = 0; ax < 3; ++ax)
      if (b.has_word(kAxisLetter[ax])) axis_ref(m, ax) = axis_val(to, ax);
    to = frame_of_machine(nx, m);
  }
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  if ((e = check_pos(to, motion_col(), w)) != GcodeError::kOk) return e;
  if (motion != 0 && motion != 330 && motion != 331) {  // G1, or a probe move (G33's feed is K x S)
    if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, motion_col(), w);
    if (!nx.inverse_time && (e = need_feed(motion_col(), w)) != GcodeError::kOk) return e;
    if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  }
  plan.motion = Plan::kStraight;
  plan.straight_kind = motion == 0 ? CanonKind::kTraverse : CanonKind::kFeed;
  plan.target = to;
  plan.inverse_time = nx.inverse_time && motion != 0;
  nx.pos = to;
  if (motion != 0 && motion != 10) return GcodeError::kOk;
  nx.comp.arc_not_allowed = false;  // any G0/G1 allows arcs again after G40
  return nx.comp.side ? comp_straight(motion, g53, to) : GcodeError::kOk;
}

GcodeError BlockRunner::run_arc(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  const Plane pl = nx.plane;
  const int ia = plane_axis_a(pl), ib = plane_axis_b(pl);
  const PointNm base = comp_base();
  if (nx.comp.arc_not_allowed) return fail(GcodeError::kCompArcAfterExit, col, w);
  // I, J, K belong to X, Y, Z; the one along the plane's axis is an error.
  const char off_letter[3] = {'I', 'J', 'K'};
  const char not_here = off_letter[plane_axis_c(pl)];
  if (b.has_word(not_here)) return fail_letter(GcodeError::kArcWordWrongPlane, not_here);
  const bool has_r = b.has_word('R');
  const bool has_ijk = b.has_word(off_letter[ia]) || b.has_word(off_letter[ib]);
  if (!has_r && !has_ijk) return fail(GcodeError::kArcNoCentre, col, w);
  if (has_r && has_ijk) return fail_letter(GcodeError::kArcRAndIjk, 'R');
  PointNm to;
  if ((e = end_point(&to)) != GcodeError::kOk) return e;
  if ((e = check_pos(to, col, w)) != GcodeError::kOk) return e;
  int64_t turns = 1;
  if (b.has_word('P')) {
    if (!decimal_to_int(b.val('P'), &turns) || turns < 1) return fail_letter(GcodeError::kTurnsNotPositive, 'P');
    if (turns > kMaxTurns) return fail_letter(GcodeError::kNumberTooLarge, 'P');
  }
  if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, col, w);
  if (!nx.inverse_time && (e = need_feed(col, w)) != GcodeError::kOk) return e;
  if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  const ArcPlanar p{axis_val(base, ia), axis_val(base, ib), axis_val(to, ia), axis_val(to, ib)};
  int64_t ca, cb;
  if (has_r) {
    int64_t r;
    if ((e = length('R', &r, kGcodeMaxArcNm)) != GcodeError::kOk) return e;
    if (nx.comp.side && (e = comp_arc_entry(motion, to, true, abs64(r))) != GcodeError::kOk) return e;
    e = arc_centre_from_radius(p, r, motion == 20, &ca, &cb, &d->a_nm, &d->b_nm);
    if (e != GcodeError::kOk) return fail(e, b.g[kGMotion] >= 0 ? col : b.col_of('R'), w);
  } else {
    if (nx.comp.side && (e = comp_arc_entry(motion, to, false, 0)) != GcodeError::kOk) return e;
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
  const int64_t sc = axis_val(base, plane_axis_c(pl));
  plan.motion = Plan::kArc;
  plan.target = to;
  plan.arc.plane = pl;
  plan.arc.centre = plane_point(pl, ca, cb, sc);
  plan.arc.turns = static_cast<int32_t>(motion == 20 ? -turns : turns);
  plan.inverse_time = nx.inverse_time;
  nx.pos = to;
  return nx.comp.side ? comp_arc(motion, to, ca, cb) : GcodeError::kOk;
}

}  // namespace dexmill
