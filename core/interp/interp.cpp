// The RS274/NGC interpreter: checks a block against the modal state, then
// commits it. The order of execution within a block is LinuxCNC's
// (rs274ngc, execute_block / convert_*): feed mode, F, S, T, M6, spindle,
// coolant, dwell, plane, units, cutter compensation, tool length offset,
// coordinate system, path control, distance modes, retract mode, G10 / G28
// / G30 / G92, motion, stop. This file runs a block's steps in that order
// and commits it; the steps are in interp_modes.cpp and interp_moves.cpp
// (core/interp/block_runner.h).
#include "core/interp/interp.h"
#include "core/gcode/lex.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"
#include "core/canon/arc_chords.h"
#include "core/interp/block_runner.h"

namespace dexmill {

namespace {

// Length of a 3D segment, nm (exact floor).
int64_t seg_length(const PointNm& a, const PointNm& b) {
  U128 s = u128_add(sum_sq_u128(b.x_nm - a.x_nm, b.y_nm - a.y_nm), sq_u128(b.z_nm - a.z_nm));
  return static_cast<int64_t>(isqrt_u128(s));
}

}  // namespace


GcodeError BlockRunner::run() {
  const int g0 = b.g[kGNonModal];
  const int gm = b.g[kGMotion];
  const bool tlo_axes = b.g[kGToolLength] == 431 || b.g[kGToolLength] == 432;
  const bool axis_user0 = g0 == 100 || g0 == 280 || g0 == 300 || g0 == 920 || tlo_axes;
  if (b.has_polar()) {  // LinuxCNC checks polar words first (interp_polar.cpp)
    const GcodeError e = check_polar(axis_user0);
    if (e != GcodeError::kOk) return e;
  }
  if (gm >= 0 && gm != 800 && axis_user0) {
    return fail_code(GcodeError::kTwoAxisUsers, 'G', static_cast<int16_t>(tlo_axes ? b.g[kGToolLength] : g0),
                     tlo_axes ? b.g_col[kGToolLength] : b.g_col[kGNonModal]);
  }
  int motion = -1;  // the motion this block makes, in tenths
  if (gm >= 0) {
    motion = gm;
  } else if (b.has_axis() && !axis_user0) {
    motion = cur.motion;
  }
  if (b.has_axis() && !axis_user0 && motion == 800) {
    if (gm == 800) return fail_code(GcodeError::kAxisWordsWithG80, 'G', 800, b.g_col[kGMotion]);
    const char ax = b.has_word('X') ? 'X' : b.has_word('Y') ? 'Y' : b.has_word('Z') ? 'Z' : polar_letter();
    return fail_letter(GcodeError::kAxisWordsUnused, ax);
  }
  GcodeError e = check_unused(g0, motion);
  if (e != GcodeError::kOk) return e;
  e = run_modes();
  if (e != GcodeError::kOk) return e;
  if (plan.rest_skipped) return GcodeError::kOk;  // M72 (run_context)
  if (g0 >= 0 && g0 != 530 && g0 != 40) {
    e = run_group0(g0);
    if (e != GcodeError::kOk) return e;
  }
  if (g0 == 530 && motion != 0 && motion != 10) return fail_code(GcodeError::kG53BadMotion, 'G', 530, b.g_col[kGNonModal]);
  if (motion >= 0) {
    e = run_motion(motion);
    if (e != GcodeError::kOk) return e;
  }
  // A move starts from where the tool is (cur.pos + cur.stray) and ends
  // where the interpreter reckons; only cycles leave the two apart.
  // A rigid tap comes back to where the tool began.
  if (plan.motion != Plan::kNone && plan.motion != Plan::kCycle && plan.motion != Plan::kTap) nx.stray = PointNm{0, 0, 0};
  if (b.m[kMStop] >= 0) {
    plan.stop = b.m[kMStop];
    if (plan.stop == 20 || plan.stop == 300) {
      nx.ended = true;
      nx.comp.side = 0;  // LinuxCNC's program end turns compensation off
      nx.comp.first_move = true;
    }
  }
  return comp_acts() ? comp_check_queue() : GcodeError::kOk;
}

// Words that no code of the block uses are errors, as in LinuxCNC.
GcodeError BlockRunner::check_unused(int g0, int motion) {
  const bool arc = motion == 20 || motion == 30;
  const bool spline = motion == 50 || motion == 51;  // G5 takes I, J, P, Q; G5.1 I, J
  const bool cycle = is_cycle(motion);
  const bool user_m = b.m[kMUser] >= 0 || b.m[kMIo] >= 0;
  const int path = b.g[kGPathControl];
  if (!arc && motion != 870) {  // G87 takes I, J, K (its offset and the back bore's top)
    const char ijk[3] = {'I', 'J', 'K'};
    const bool sync = motion == 330 || motion == 331;  // G33/G33.1 take K, the pitch
    for (char c : ijk)
      if (b.has_word(c) && !(spline && c != 'K') && !(sync && c == 'K')) return fail_letter(GcodeError::kWordUnused, c);
  }
  // LinuxCNC lets G41.1/G42.1 have an R word (and uses none).
  const bool comp_dia = b.g[kGCutterComp] == 411 || b.g[kGCutterComp] == 421;
  if (b.has_word('R') && !arc && !cycle && g0 != 100 && !comp_dia) return fail_letter(GcodeError::kWordUnused, 'R');
  const bool dwell_cycle = motion == 740 || motion == 820 || motion == 840 || motion == 860 || motion == 880 || motion == 890;
  if (b.has_word('P') && !(g0 == 40 || g0 == 100 || path == 640 || arc || dwell_cycle || user_m || motion == 50 || motion == 52))
    return fail_letter(GcodeError::kWordUnused, 'P');
  if (b.has_word('Q') &&
      !(motion == 730 || motion == 830 || path == 640 || b.m[kMToolChange] == 610 || user_m || motion == 50))
    return fail_letter(GcodeError::kWordUnused, 'Q');
  // LinuxCNC 2.9 takes no L with G74 (its check of L lists every cycle but it).
  const bool comp_on = b.g[kGCutterComp] > 400;  // G41, G41.1, G42, G42.1
  if (b.has_word('L') && !(g0 == 100 || (cycle && motion != 740) || comp_on || motion == 52))
    return fail_letter(GcodeError::kWordUnused, 'L');
  if (b.has_word('H') && b.g[kGToolLength] == 490) {
    // Centroid's posts write `G49 H0`: the H changes nothing G49 does.
    warn_once(kOnceG49H, GcodeError::kWarnG49H, b.col_of('H'), "G49");
  } else if (b.has_word('H') && b.g[kGToolLength] != 430 && b.g[kGToolLength] != 432) {
    return fail_letter(GcodeError::kWordUnused, 'H');
  }
  if (b.has_word('D') && !comp_on) return fail_letter(GcodeError::kWordUnused, 'D');
  return GcodeError::kOk;
}

namespace {

// Feeds a cycle's moves to the sink as records.
struct CycleRecords final : CycleOut {
  Interp* in;
  CanonRecord* base;
  PointNm at;
  void (*emit)(Interp*, CanonRecord*);
  void move(CanonKind kind, const PointNm& to) override {
    base->kind = kind;
    base->start = at;
    base->end = to;
    at = to;
    emit(in, base);
  }
  void dwell(int64_t ms) override {
    base->kind = CanonKind::kDwell;
    base->start = base->end = at;
    base->dwell_ms = ms;
    emit(in, base);
    base->dwell_ms = 0;
  }
  // The spindle a cycle stops, reverses or restarts: later records carry it.
  void spindle(int32_t rpm) override {
    base->kind = CanonKind::kSpindle;
    base->start = base->end = at;
    base->spindle_rpm = rpm;
    emit(in, base);
  }
  void pause() override {
    base->kind = CanonKind::kPause;
    base->start = base->end = at;
    emit(in, base);
  }
};

// Length of an arc or helix record, nm (for G93 feed rates).
int64_t arc_length(const CanonRecord& r) {
  ArcChords ch;
  ch.init(r, 1000000);
  const Plane p = r.arc.plane;
  const int64_t ra = hypot_floor(plane_a(p, r.start) - plane_a(p, r.arc.centre), plane_b(p, r.start) - plane_b(p, r.arc.centre));
  int64_t sweep = ch.sweep_bam();
  if (sweep < 0) sweep = -sweep;
  // r * sweep * 2 pi / 2^32, with 2 pi = 6283185307 / 1e9.
  const int64_t planar = muldiv_round(muldiv_round(ra, sweep, static_cast<int64_t>(1) << 32), 6283185307, 1000000000);
  const int64_t dc = plane_c(p, r.end) - plane_c(p, r.start);
  return static_cast<int64_t>(isqrt_u128(sum_sq_u128(planar, dc)));
}

}  // namespace

void BlockRunner::commit() {
  Interp& I = in;
  // G10 on the system in force, or an M72 that restores another, under a
  // turned frame: the tool stays, its point is worked out in the new frame
  // (a G54-G59.3 word was, before the block ran). Neither moves in the block.
  if (b.g[kGCoordSystem] < 0 && plan.motion == Plan::kNone && frame_moved(cur, nx)) Interp::reframe_tool(&nx, cur);
  const PointNm start = tool_at(cur);
  I.state_ = nx;
  note_units(start);
  CanonRecord r{};
  r.line = b.line;
  r.start = r.end = start;
  r.arc = CanonArc{Plane::kXY, start, 1};
  // G95: the rate is F per revolution times the speed in force at the move.
  r.feed_nm_per_min = nx.per_rev ? sync_feed(nx.feed_nm_per_min, nx.spindle_rpm) : nx.feed_nm_per_min;
  r.tool = nx.tool;
  r.tool_length_offset_nm = nx.tlo_nm;
  r.path_mode = static_cast<uint16_t>(nx.path_mode);
  r.path_tolerance_nm = nx.path_tolerance_nm;
  if (plan.nurbs_add) {  // G5.2: one more control point
    NurbsCurve& c = I.nurbs_;
    if (plan.nurbs_add == 2) {
      c.count = 1;
      c.x_nm[0] = cur.pos.x_nm;
      c.y_nm[0] = cur.pos.y_nm;
      c.weight[0] = plan.nurbs_first_weight;
    }
    c.order = plan.nurbs_order;
    if (plan.nurbs_has_point) {
      c.x_nm[c.count] = plan.nurbs_x;
      c.y_nm[c.count] = plan.nurbs_y;
      c.weight[c.count] = plan.nurbs_weight;
      ++c.count;
    }
  }
  if (plan.context_op >= 0) {  // M70, M71, M73
    if (plan.context_op == 710) I.contexts_[I.context_level()].valid = false;
    else I.contexts_[I.context_level()] = plan.context;
  }
  if (plan.tool_change) {
    r.kind = CanonKind::kToolChange;
    I.emit(&r);
  }
  if (plan.spindle) {
    r.kind = CanonKind::kSpindle;
    r.spindle_rpm = nx.spindle_dir * nx.spindle_rpm;
    I.emit(&r);
  }
  r.spindle_rpm = nx.spindle_dir * nx.spindle_rpm;
  if (plan.coolant) {
    r.kind = CanonKind::kCoolant;
    r.coolant = nx.coolant;
    I.emit(&r);
  }
  r.coolant = nx.coolant;
  if (plan.dwell) {
    r.kind = CanonKind::kDwell;
    r.dwell_ms = plan.dwell_ms;
    I.emit(&r);
    r.dwell_ms = 0;
  }
  if (plan.comp.off_flush) comp_commit_flush(start);
  if (plan.comp.motion) {
    if (plan.inverse_time) {  // LinuxCNC: the programmed move's length
      CanonRecord prog = r;
      prog.start = plan.comp.prog_start;
      prog.end = plan.target;
      prog.arc = plan.arc;
      r.feed_nm_per_min = decimal_scale(plan.inverse_f, plan.motion == Plan::kArc ? arc_length(prog)
                                                                                  : seg_length(prog.start, prog.end));
    }
    comp_commit_motion(&r, start);
    plan.motion = Plan::kNone;
  }
  switch (plan.motion) {
    case Plan::kNone:
      break;
    case Plan::kStraight:
      r.kind = plan.straight_kind;
      r.end = plan.target;
      if (plan.inverse_time) r.feed_nm_per_min = decimal_scale(plan.inverse_f, seg_length(start, plan.target));
      if (plan.sync_feed_nm_per_min) r.feed_nm_per_min = plan.sync_feed_nm_per_min;  // G33
      I.emit(&r);
      break;
    case Plan::kTap:  // G33.1: in and back out along the same line
      r.kind = CanonKind::kFeed;
      r.feed_nm_per_min = plan.sync_feed_nm_per_min;
      r.end = plan.target;
      I.emit(&r);
      r.start = plan.target;
      r.end = start;
      I.emit(&r);
      break;
    case Plan::kArc:
      r.kind = CanonKind::kArc;
      r.end = plan.target;
      r.arc = plan.arc;
      if (plan.inverse_time) r.feed_nm_per_min = decimal_scale(plan.inverse_f, arc_length(r));
      I.emit(&r);
      break;
    case Plan::kSpline:
      commit_spline(&r);
      break;
    case Plan::kNurbs:
      commit_nurbs(&r);
      break;
    case Plan::kHome:
      r.kind = CanonKind::kTraverse;
      r.end = plan.home_via;
      I.emit(&r);
      r.start = plan.home_via;
      r.end = plan.target;
      I.emit(&r);
      break;
    case Plan::kCycle: {
      CycleRecords out;
      out.in = &I;
      out.base = &r;
      out.at = start;
      out.emit = [](Interp* interp, CanonRecord* rec) { interp->emit(rec); };
      cycle_emit(plan.cycle, &out);
      break;
    }
  }
  if (plan.stop >= 0) {
    if (I.comp_q_.n) comp_commit_flush(nx.pos);
    r.start = r.end = tool_at(nx);
    r.kind = (plan.stop == 20 || plan.stop == 300) ? CanonKind::kEnd : CanonKind::kPause;
    I.emit(&r);
  }
}

// The units the block's moves and T are read in: a move before any
// G20/G21 is warned of once (InterpOptions::units_given), at the column
// of its motion code or first axis word.
void BlockRunner::note_units(const PointNm& start) {
  Interp& I = in;
  if (b.g[kGUnits] >= 0) I.units_set_ = true;
  // The feed in force is one the program wrote (not --default-feed's): an
  // F word; G93/G94/G95 clear it.
  if (b.has_word('F')) I.feed_written_ = true;
  else if (b.g[kGFeedMode] >= 0) I.feed_written_ = false;
  if (b.has_word('T') && !I.tool_named_) {
    I.tool_named_ = true;
    I.units_at_tool_ = I.units_set_;
    I.inch_at_tool_ = nx.inch;
  }
  // A G0 or G1 that goes nowhere (a post's `G53 G0` with no axis word) reads no length.
  const bool still = plan.motion == Plan::kStraight && plan.target == start;
  const bool moves = (plan.motion != Plan::kNone && !still) || plan.comp.motion;
  if (!moves || I.units_set_ || I.unset_move_line_) return;
  uint16_t col = b.g[kGMotion] >= 0 ? b.g_col[kGMotion] : b.g[kGNonModal] >= 0 ? b.g_col[kGNonModal] : 0;
  const char axes[3] = {'X', 'Y', 'Z'};
  for (char c : axes)
    if (!col && b.has_word(c)) col = b.col_of(c);
  I.unset_move_line_ = b.line;
  I.unset_move_col_ = col ? col : b.first_col;
  if (!I.options_.units_given) I.warn(GcodeError::kWarnUnitsNotSet, b.line, I.unset_move_col_, nx.inch ? "inch" : "mm");
}

void BlockRunner::warn_once(uint16_t bit, GcodeError e, uint16_t col, const char* word, int64_t a_nm) {
  if (in.warned_once_ & bit) return;
  in.warned_once_ = static_cast<uint16_t>(in.warned_once_ | bit);
  in.warn(e, b.line, col, word, a_nm);
}

Interp::Interp(CanonSink* sink, const InterpOptions& options) : sink_(sink), options_(options) { reset(); }

void Interp::reset() {
  state_ = InterpState{};
  state_.motion = 800;
  state_.plane = Plane::kXY;
  state_.inch = options_.inch;
  state_.path_mode = 640;
  // LinuxCNC's interpreter starts in G99 (retract to R): its init sets
  // R_PLANE; a machine's RS274NGC_STARTUP_CODE may say G98.
  state_.retract_to_r = true;
  state_.comp.first_move = true;
  if (options_.work_offsets)
    for (int k = 0; k < 9; ++k) state_.work_offset[k] = options_.work_offsets[k];
  state_.coord_system = options_.start_coord_system < 9 ? options_.start_coord_system : 0;
  state_.g92 = options_.start_g92;
  state_.tlo_nm = options_.start_tlo_nm;
  if (options_.start_given) {
    state_.pos = options_.start_pos;
    state_.tool = state_.selected_tool = options_.start_tool;
  }
  records_ = 0;
  moves_ = 0;
  probe_moves_ = 0;
  any_code_ = false;
  any_failed_ = false;
  suspect_ = 0;
  warned_after_end_ = false;
  sub_after_end_ = false;
  if (ParamStore* p = options_.params) {
    params_clear(p);
    p->system.read = &Interp::read_param;
    p->system.ctx = this;
  }
  if (options_.control) oword_store_clear(options_.control);
  warned_once_ = 0;
  units_set_ = false;
  unset_move_line_ = 0;
  unset_move_col_ = 0;
  units_ev_ = UnitsEvidence{};
  tool_named_ = units_at_tool_ = inch_at_tool_ = feed_written_ = false;
  comp_q_.clear();
  comp_scratch_.clear();
  for (ModalContext& c : contexts_) c.valid = false;
  nurbs_.count = 0;
}

GcodeError Interp::context_return(int level, uint32_t line, uint16_t col, GcodeDiag* d) {
  ModalContext& c = contexts_[level];
  const bool restore = c.valid && c.auto_restore;
  c.valid = false;
  if (!restore) return GcodeError::kOk;
  if (c.comp_side != state_.comp.side) {
    d->code = GcodeError::kUnsupportedContextComp;
    d->col = col;
    gcode_set_word(d, "M73", 3);
    return d->code;
  }
  InterpState s = state_;
  modal_context_apply(c, &s);
  // A turned frame given back: the tool stays, its point worked out anew;
  // the spindle stays where it is: the tool tip moves by the offset's change (as G43).
  if (frame_moved(state_, s)) reframe_tool(&s, state_);
  s.pos.z_nm -= s.tlo_nm - state_.tlo_nm;
  CanonRecord r{};
  r.line = line;
  r.start = r.end = tool_at(s);
  r.arc = CanonArc{Plane::kXY, r.start, 1};
  r.feed_nm_per_min = s.feed_nm_per_min;
  r.tool = s.tool;
  r.tool_length_offset_nm = s.tlo_nm;
  r.path_mode = static_cast<uint16_t>(s.path_mode);
  r.path_tolerance_nm = s.path_tolerance_nm;
  r.spindle_rpm = s.spindle_dir * s.spindle_rpm;
  r.coolant = s.coolant;
  const bool spindle = r.spindle_rpm != state_.spindle_dir * state_.spindle_rpm, coolant = s.coolant != state_.coolant;
  state_ = s;
  if (spindle) {
    r.kind = CanonKind::kSpindle;
    emit(&r);
  }
  if (coolant) {
    r.kind = CanonKind::kCoolant;
    emit(&r);
  }
  return GcodeError::kOk;
}

PointNm Interp::reframe(const InterpState& from, const InterpState& to, const PointNm& p) {
  if (!rotated(from) && !rotated(to)) return p;  // both the machine frame: nothing moves
  return frame_of_machine(to, machine_of(from, p));
}

void Interp::reframe_tool(InterpState* s, const InterpState& from) {
  const PointNm tool = reframe(from, *s, tool_at(from)), pos = reframe(from, *s, from.pos);
  s->pos = pos;
  s->stray = PointNm{tool.x_nm - pos.x_nm, tool.y_nm - pos.y_nm, tool.z_nm - pos.z_nm};
}

void Interp::emit_now(CanonRecord* r) {
  if (rotated(state_) && r->kind == CanonKind::kArc && r->arc.plane != Plane::kXY) {
    // A turned G18/G19 arc leaves its plane, which no CanonArc can say: it
    // goes out as chords of --chord's sagitta (arc_chords.h), each turned.
    ArcChords chords;
    chords.init(*r, options_.spline_sagitta_nm);
    CanonRecord f = *r;
    f.kind = CanonKind::kFeed;
    PointNm p;
    while (chords.next(&p)) {
      f.end = p;
      CanonRecord g = f;
      emit_now(&g);
      f.start = p;
    }
    return;
  }
  if (rotated(state_)) {  // records go out in the machine frame (rotation.h)
    r->start = machine_of(state_, r->start);
    r->end = machine_of(state_, r->end);
    r->arc.centre = machine_of(state_, r->arc.centre);
  }
  if (!units_set_ && !options_.inch && !options_.units_given)
    units_evidence_add(&units_ev_, *r, feed_written_ || state_.inverse_time);
  ++records_;
  const bool straight = r->kind == CanonKind::kTraverse || r->kind == CanonKind::kFeed;
  if (r->kind == CanonKind::kArc || (straight && !(r->start == r->end))) ++moves_;
  if (sink_) sink_->emit(*r);
}

void Interp::warn(GcodeError code, uint32_t line, uint16_t col, const char* word, int64_t a_nm, int64_t b_nm) {
  if (!options_.warnings) return;
  GcodeDiag d{};
  d.code = code;
  d.a_nm = a_nm;
  d.b_nm = b_nm;
  d.line = line;
  d.col = col ? col : 1;
  int i = 0;
  for (; word && word[i] && i < 15; ++i) d.word[i] = word[i];
  d.word[i] = 0;
  options_.warnings->warning(d);
}

GcodeError Interp::execute_line(const char* text, size_t len, uint32_t line, GcodeDiag* diag) {
  if (OwordStore* c = options_.control; c && options_.params && !state_.ended) {
    // An endless loop stops here, once (nothing after it is run).
    if (c->looped && options_.max_blocks && c->blocks >= options_.max_blocks) {
      diag->code = GcodeError::kBlockLimit;
      diag->line = c->loop_line;
      diag->col = 1;
      diag->word[0] = 0;
      diag->a_nm = static_cast<int64_t>(options_.max_blocks);
      diag->b_nm = c->loop_line;
      diag->follow_on = false;
      state_.ended = warned_after_end_ = any_failed_ = true;
      return GcodeError::kBlockLimit;
    }
    ++c->blocks;
    const bool skipping = oword_skipping();
    const bool oline = oword_line_fast(text, len);
    if (skipping || oline) {
      if (!skipping) any_code_ = true;
      if (!oline) return GcodeError::kOk;  // passed over unread, as in LinuxCNC
      diag->follow_on = false;
      const GcodeError e = run_oword(text, len, line, diag);
      if (e != GcodeError::kOk) {
        // The flow after a bad statement is unknown: what follows may be its consequence.
        any_failed_ = true;
        suspect_ = kFacetAll;
        diag->line = line;
      }
      return e;
    }
  }
  GcodeBlock block;
  GcodeLineKind kind;
  // Nothing after the end is read, not even an assignment.
  GcodeError e = gcode_read_block(text, len, line, &block, &kind, diag, state_.ended ? nullptr : options_.params);
  diag->follow_on = false;
  if (state_.ended) {
    // RS274/NGC: nothing after the end is read. Say so once if it looks like
    // code; subroutines after the end are for calls made before it.
    if (options_.control && options_.params && oword_line(text, len)) {
      OwordHead h;
      GcodeDiag ignored;
      if (oword_read_head(text, len, *options_.params, &h, &ignored) == GcodeError::kOk) {
        if (h.op == OwordOp::kSub || h.op == OwordOp::kProgramNumber) sub_after_end_ = true;
        if (h.op == OwordOp::kEndsub || h.op == OwordOp::kM99) sub_after_end_ = false;
      }
      return GcodeError::kOk;
    }
    if (sub_after_end_) return GcodeError::kOk;
    if (!warned_after_end_ && (e != GcodeError::kOk || (kind == GcodeLineKind::kBlock && block.has) ||
                               kind == GcodeLineKind::kGrblCommand)) {
      warned_after_end_ = true;
      warn(GcodeError::kWarnAfterEnd, line, 1, "");
    }
    return GcodeError::kOk;
  }
  if (e != GcodeError::kOk || kind == GcodeLineKind::kGrblCommand || (kind == GcodeLineKind::kBlock && !block.empty()))
    any_code_ = true;
  if (e != GcodeError::kOk) {
    // The line's own words are wrong: a root error, whatever came before.
    any_failed_ = true;
    suspect_ |= facets_written(text, len);
    return e;
  }
  switch (kind) {
    case GcodeLineKind::kPercent:
      // The first % opens the program; a second one ends it.
      if (state_.percent_open) state_.ended = true;
      state_.percent_open = true;
      return GcodeError::kOk;
    case GcodeLineKind::kProgramNumber:
      return GcodeError::kOk;
    case GcodeLineKind::kGrblCommand:
      warn(GcodeError::kWarnGrblCommand, line, diag->col, diag->word);
      return GcodeError::kOk;
    case GcodeLineKind::kBlock:
      break;
  }
  // Ignored M codes: warn, then run the rest of the block.
  const int ignored_groups[3] = {kMOverride, kMIo, kMUser};
  for (int g : ignored_groups) {
    if (block.m[g] >= 0) {
      char w[16];
      gcode_code_text('M', block.m[g], w);
      const bool remap = g == kMUser && block.m[g] < 1000;  // not one of LinuxCNC's M100-M199
      warn(remap ? GcodeError::kWarnMcodeMachine : GcodeError::kWarnMcodeIgnored, line, block.m_col[g], w);
    }
  }
  if (block.m[kMSpindle] == 190) warn(GcodeError::kWarnMcodeIgnored, line, block.m_col[kMSpindle], "M19");
  // A switch of work coordinate system under a turned frame: the tool's
  // point in the new frame before the block reads its words (LinuxCNC's
  // convert_coordinate_system), given back if the block fails.
  PointNm pos_before, stray_before;
  const bool reframed = block.g[kGCoordSystem] >= 0 && rotation_any();
  if (reframed) {
    pos_before = state_.pos;
    stray_before = state_.stray;
    const int g = block.g[kGCoordSystem];
    InterpState to = state_;
    to.coord_system = static_cast<uint8_t>(g <= 590 ? (g - 540) / 10 : 6 + (g - 591));
    reframe_tool(&to, state_);
    state_.pos = to.pos;
    state_.stray = to.stray;
  }
  BlockRunner run(*this, block, diag);
  e = run.run();
  if (e != GcodeError::kOk && reframed) {
    state_.pos = pos_before;
    state_.stray = stray_before;
  }
  const uint16_t set = facets_set(block, state_, suspect_);
  if (e != GcodeError::kOk) {
    any_failed_ = true;
    const ErrorFacets f = error_facets(e, block);
    diag->follow_on = ((f.read & suspect_after(suspect_, set)) | (f.before_block & suspect_)) != 0;
    suspect_ |= facets_written(text, len) | f.blamed;
    diag->line = line;
    return e;
  }
  run.commit();
  suspect_ = suspect_after(suspect_, set);
  if (block.message_kind != GcodeMessage::kNone && options_.messages)
    options_.messages->message(line, static_cast<int>(block.message_kind), block.message);
  return GcodeError::kOk;
}

void Interp::line_not_read() {
  if (state_.ended) return;  // nothing after the end is read anyway
  any_code_ = any_failed_ = true;
  suspect_ = kFacetAll;
}

GcodeError Interp::end_of_input(uint32_t last_line, GcodeDiag* diag) {
  // Moves cutter compensation still holds go as they are (a program that
  // ends without M2, or ends in error).
  const CompEmit out{[](void* ctx, CanonRecord* r) { static_cast<Interp*>(ctx)->emit_now(r); }, this};
  comp_q_.dequeue(&out, state_.pos);
  if (units_verdict() == UnitsVerdict::kLookInch)
    warn(GcodeError::kWarnUnitsLookInch, unset_move_line_, unset_move_col_, "", units_ev_.extent_nm(),
         units_ev_.feed_max_nm_per_min);
  GcodeDiag unclosed{};
  if (!state_.ended && oword_unclosed(&unclosed) != GcodeError::kOk) {
    any_failed_ = true;
    if (diag) *diag = unclosed;
    return unclosed.code;
  }
  if (!any_code_) {
    warn(GcodeError::kWarnEmptyProgram, 1, 1, "");
    return GcodeError::kOk;
  }
  // A failed block may have been the end (M2 in it): then no verdict.
  if (!state_.ended && !(suspect_ & kFacetEnd))
    warn(state_.percent_open ? GcodeError::kWarnNoClosingPercent : GcodeError::kWarnNoProgramEnd,
         last_line ? last_line : 1, 1, "");
  if (!any_failed_ && moves_ == 0) warn(GcodeError::kWarnNoMotion, 1, 1, "");
  return GcodeError::kOk;
}

UnitsVerdict Interp::units_verdict() const {
  if (!unset_move_line_) return UnitsVerdict::kSet;
  if (options_.units_given) return UnitsVerdict::kGiven;
  if (!units_set_ && !options_.inch && units_look_like_inch(units_ev_)) return UnitsVerdict::kLookInch;
  return UnitsVerdict::kDefault;
}

uint32_t interp_run_source(Interp* in, MemorySource* src, GcodeDiag* first) {
  uint32_t errors = 0, line = 0, last = 0;
  const char* text = nullptr;
  size_t len = 0;
  in->set_source(src);
  while (src->next(&text, &len, &line)) {
    if (line > last) last = line;
    GcodeDiag d;
    if (in->execute_line(text, len, line, &d) != GcodeError::kOk) {
      if (errors++ == 0 && first) *first = d;
    }
  }
  GcodeDiag d;
  if (in->end_of_input(last, &d) != GcodeError::kOk) {
    if (errors++ == 0 && first) *first = d;
  }
  return errors;
}

uint32_t interp_run_text(Interp* in, const char* text, size_t len, GcodeDiag* first) {
  MemorySource src(text, len);
  return interp_run_source(in, &src, first);
}

}  // namespace dexmill
