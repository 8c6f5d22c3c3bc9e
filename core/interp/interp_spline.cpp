// G5 (cubic spline) and G5.1 (quadratic B-spline) as LinuxCNC 2.9 reads
// them (interp_convert.cc convert_spline): XY plane only, no Z, I and J the
// first handle from the start, G5's P and Q the second from the end. A G5
// without I and J continues the curve before it: its handle is the last
// G5's second one reflected (LinuxCNC keeps -P, -Q in its cycle_i, cycle_j,
// which G87 shares: so does dexmill, in cycle_ijk_nm). LinuxCNC 2.9 does
// not make G5 or G5.1 the modal motion: a later line of bare X and Y moves
// by the motion before them (its rs274 shows it). The curve becomes chords
// of bounded sagitta (core/interp/spline.h).
#include "core/math/wide.h"
#include "core/interp/block_runner.h"

namespace dexmill {

GcodeError BlockRunner::run_spline(int motion) {
  GcodeError e;
  char w[16];
  gcode_code_text('G', static_cast<int16_t>(motion), w);
  const uint16_t col = motion_col();
  const bool cubic = motion == 50;
  nx.cycle_level_set = false;  // any motion but a cycle ends a cycle series
  if (!b.has_axis()) return fail(GcodeError::kSplineNoAxis, col, w);
  if (nx.inverse_time && !b.has_word('F')) return fail(GcodeError::kInverseTimeNoF, col, w);
  if (!nx.inverse_time && (e = need_feed(col, w)) != GcodeError::kOk) return e;
  if (nx.inverse_time && decimal_is_zero(plan.inverse_f)) return fail_letter(GcodeError::kFeedZero, 'F');
  if (nx.plane != Plane::kXY) return fail(GcodeError::kSplinePlane, col, w);
  if (b.has_word('Z')) return fail_letter(GcodeError::kSplineZ, 'Z');
  const bool has_i = b.has_word('I'), has_j = b.has_word('J');
  if (has_i != has_j || (!cubic && !has_i)) return fail(GcodeError::kSplineIJ, has_i ? b.col_of('I') : has_j ? b.col_of('J') : col, w);
  int64_t i = nx.cycle_ijk_nm[0], j = nx.cycle_ijk_nm[1];
  if (has_i && ((e = length('I', &i)) != GcodeError::kOk || (e = length('J', &j)) != GcodeError::kOk)) return e;
  PointNm to;
  if ((e = end_point(&to)) != GcodeError::kOk) return e;  // (no Z: checked above)
  int64_t p = 0, q = 0;
  if (cubic) {
    if (!b.has_word('P') || !b.has_word('Q')) return fail(GcodeError::kSplinePQ, col, w);
    if ((e = length('P', &p)) != GcodeError::kOk || (e = length('Q', &q)) != GcodeError::kOk) return e;
  }
  if ((e = check_pos(to, col, w)) != GcodeError::kOk) return e;
  SplinePlan& s = plan.spline;
  s.points = cubic ? 4 : 3;
  s.x[0] = cur.pos.x_nm;
  s.y[0] = cur.pos.y_nm;
  s.x[1] = cur.pos.x_nm + i;
  s.y[1] = cur.pos.y_nm + j;
  if (cubic) {
    s.x[2] = to.x_nm + p;
    s.y[2] = to.y_nm + q;
  }
  s.x[s.points - 1] = to.x_nm;
  s.y[s.points - 1] = to.y_nm;
  s.z_nm = cur.pos.z_nm;
  s.chords = spline_chord_count(s, in.options_.spline_sagitta_nm);
  // Every chord point in range; their length for G93.
  s.length_nm = 0;
  int64_t ax = s.x[0], ay = s.y[0];
  for (uint32_t k = 1; k <= s.chords; ++k) {
    int64_t x, y;
    spline_point(s, k, &x, &y);
    if ((e = check_pos(PointNm{x, y, s.z_nm}, col, w)) != GcodeError::kOk) return e;
    s.length_nm += hypot_floor(x - ax, y - ay);
    ax = x;
    ay = y;
  }
  if (cubic) {
    nx.cycle_ijk_nm[0] = -p;
    nx.cycle_ijk_nm[1] = -q;
  }
  plan.motion = Plan::kSpline;
  plan.inverse_time = nx.inverse_time;
  nx.pos = to;
  return GcodeError::kOk;
}

void BlockRunner::commit_spline(CanonRecord* r) {
  const SplinePlan& s = plan.spline;
  r->kind = CanonKind::kFeed;
  if (plan.inverse_time) r->feed_nm_per_min = decimal_scale(plan.inverse_f, s.length_nm);
  for (uint32_t k = 1; k <= s.chords; ++k) {
    spline_point(s, k, &r->end.x_nm, &r->end.y_nm);
    r->end.z_nm = s.z_nm;
    in.emit(r);
    r->start = r->end;
  }
}

}  // namespace dexmill
