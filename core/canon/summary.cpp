// Motion counts, boxes, lengths and the time estimate; see summary.h.
#include "core/canon/summary.h"

#include "core/math/fixed.h"
#include "core/canon/arc_chords.h"

namespace dexmill {

void BoxAccum::add(const PointNm& p) {
  if (!valid) {
    lo = hi = p;
    valid = true;
    return;
  }
  lo.x_nm = min_of(lo.x_nm, p.x_nm); lo.y_nm = min_of(lo.y_nm, p.y_nm); lo.z_nm = min_of(lo.z_nm, p.z_nm);
  hi.x_nm = max_of(hi.x_nm, p.x_nm); hi.y_nm = max_of(hi.y_nm, p.y_nm); hi.z_nm = max_of(hi.z_nm, p.z_nm);
}

void BoxAccum::add(const BoxAccum& b) {
  if (!b.valid) return;
  add(b.lo);
  add(b.hi);
}

int64_t distance_nm(const PointNm& a, const PointNm& b) {
  const uint64_t dx = abs_u64(b.x_nm - a.x_nm), dy = abs_u64(b.y_nm - a.y_nm), dz = abs_u64(b.z_nm - a.z_nm);
  U128 s = mul_wide_u64(dx, dx);
  for (const U128 t : {mul_wide_u64(dy, dy), mul_wide_u64(dz, dz)}) {
    const uint64_t lo = s.lo + t.lo;
    s.hi += t.hi + (lo < s.lo ? 1 : 0);
    s.lo = lo;
  }
  return static_cast<int64_t>(isqrt_u128(s));
}

int64_t MotionSummary::piece_time_us(int64_t length_nm, int64_t rate_nm_per_min) {
  if (rate_nm_per_min <= 0) return 0;
  return muldiv_round(length_nm, 60 * 1000000LL, rate_nm_per_min);
}

int64_t MotionSummary::move_time_us(const MotionTimeModel& m, int64_t length_nm, int64_t rate_nm_per_min) {
  const int64_t cruise_us = piece_time_us(length_nm, rate_nm_per_min);
  if (m.accel_nm_per_s2 <= 0 || length_nm <= 0 || rate_nm_per_min <= 0) return cruise_us;
  // Trapezoid: speeding up and slowing down cover v^2 / a and take 2 v / a,
  // so the move takes L / v + v / a when L >= v^2 / a, that is when
  // L / v >= v / a; else a triangle, 2 sqrt(L / a).
  const int64_t ramp_us = muldiv_round(rate_nm_per_min, 1000000, sat_mul_i64(60, m.accel_nm_per_s2));
  if (cruise_us >= ramp_us) return sat_add_i64(cruise_us, ramp_us);
  // sqrt(L / a) s = sqrt(L * 10^12 / a) us.
  const int64_t q = muldiv_round(length_nm, 1000000000000LL, m.accel_nm_per_s2);
  return 2 * static_cast<int64_t>(isqrt_round_u64(static_cast<uint64_t>(q)));
}

MotionSummary::MotionSummary(const MotionTimeModel& model) : model_(model) {
  PlanLimits lim = model.axes;
  bool per_axis = false;
  for (int i = 0; i < 3; ++i) per_axis = per_axis || lim.accel_nm_per_s2[i] > 0;
  want_plan_ = model.blend && (per_axis || model.accel_nm_per_s2 > 0);
  if (!want_plan_) return;
  for (int i = 0; i < 3; ++i) {
    if (lim.velocity_nm_per_s[i] <= 0) lim.velocity_nm_per_s[i] = model.rapid_nm_per_min / 60;
    if (lim.accel_nm_per_s2[i] <= 0) lim.accel_nm_per_s2[i] = model.accel_nm_per_s2;
  }
  if (!per_axis) lim.max_path_nm_per_s = model.rapid_nm_per_min / 60;
  limits_ = lim;
}

void MotionSummary::set_planner(MotionPlanner* p) {
  plan_ = p;
  planning_ = want_plan_ && p;
  if (planning_) plan_->init(limits_, this);
}

int64_t arc_length_nm(const CanonRecord& r, int64_t sweep_bam, int64_t* radius_nm) {
  const Plane pl = r.arc.plane;
  const PointNm c = r.arc.centre;
  const PointNm c0{plane_a(pl, c), plane_b(pl, c), 0};
  const int64_t r0 = distance_nm(c0, PointNm{plane_a(pl, r.start), plane_b(pl, r.start), 0});
  const int64_t r1 = distance_nm(c0, PointNm{plane_a(pl, r.end), plane_b(pl, r.end), 0});
  *radius_nm = r0 / 2 + r1 / 2;
  // Mean radius times the sweep in radians; 2^32 / (2 pi) = 683565275.58.
  const int64_t around = muldiv_round(r0 / 2 + r1 / 2, static_cast<int64_t>(abs_u64(sweep_bam)), 683565276);
  const int64_t along = plane_c(pl, r.end) - plane_c(pl, r.start);
  return distance_nm(PointNm{0, 0, 0}, PointNm{around, along, 0});
}

void MotionSummary::piece(const PointNm& a, const PointNm& b, bool feed, int64_t len) {
  motion_.add(a);
  motion_.add(b);
  if (len < 0) len = distance_nm(a, b);
  if (feed) {
    feed_.add(a);
    feed_.add(b);
    feed_level_top_nm_ = max_of(feed_level_top_nm_, min_of(a.z_nm, b.z_nm));
    if (a.z_nm < 0 || b.z_nm < 0) {
      feed_below_zero_.add(a);
      feed_below_zero_.add(b);
    }
    feed_nm_ = sat_add_i64(feed_nm_, len);
  } else {
    rapid_nm_ = sat_add_i64(rapid_nm_, len);
  }
}

void MotionSummary::timed(const CanonRecord& r, bool feed, int64_t len, int64_t radius_nm) {
  const int64_t rate = feed ? min_of(r.feed_nm_per_min, model_.max_feed_nm_per_min) : model_.rapid_nm_per_min;
  const int64_t us = move_time_us(model_, len, rate);
  (feed ? feed_us_ : rapid_us_) = sat_add_i64(feed ? feed_us_ : rapid_us_, us);
  const PlanPayload p{r.tool, feed ? kMoveFeed : kMoveRapid};
  if (planning_) {  // the three figures are the planner's, of the machine's axes (planned())
    if (r.kind == CanonKind::kArc) plan_->arc(r, len, radius_nm, p);
    else plan_->line(r.start, r.end, feed ? rate : 0, r, p);
    return;
  }
  MotionTimeModel flat = model_;
  flat.accel_nm_per_s2 = 0;
  const int64_t na = move_time_us(flat, len, rate);
  const int64_t st = model_.accel_nm_per_s2 > 0 ? us : na;
  na_us_ = sat_add_i64(na_us_, na);
  st_us_ = sat_add_i64(st_us_, st);
  if (move_sink_) move_sink_->move_time(MoveTimes{r.tool, p.kind, na, st, us});
}

void MotionSummary::planned(const PlanPayload& p, const PlanTimes& t) {
  int64_t& part = p.kind == kMoveFeed ? bl_feed_us_ : bl_rapid_us_;
  part = sat_add_i64(part, t.blended_us);
  na_us_ = sat_add_i64(na_us_, t.cruise_us);
  st_us_ = sat_add_i64(st_us_, t.stop_us);
  if (move_sink_) move_sink_->move_time(MoveTimes{p.tool, p.kind, t.cruise_us, t.stop_us, t.blended_us});
}

void MotionSummary::finish() {
  if (planning_) plan_->stop();
}

void MotionSummary::emit(const CanonRecord& r) {
  const int k = static_cast<int>(r.kind);
  if (k >= 0 && k < kCanonKinds) ++counts_[k];
  switch (r.kind) {
    case CanonKind::kTraverse:
    case CanonKind::kFeed: {
      const bool feed = r.kind == CanonKind::kFeed;
      piece(r.start, r.end, feed, -1);
      timed(r, feed, distance_nm(r.start, r.end), 0);
      break;
    }
    case CanonKind::kArc: {
      // Boxes from the chords the cutter follows; length and time from the
      // arc itself (chords would be short by sagitta / (3 r) relative).
      // Long arcs (thousands of turns, metres of radius) get coarser chords,
      // sagitta r / 1000, so the scan stays cheap; the box is then within
      // r / 1000 of the arc's.
      ArcChords chords;
      chords.init(r, kArcChordSagittaNm);
      if (chords.count() > 100000) chords.init(r, chords.radius_max() / 1000);
      int64_t radius_nm = 0;
      const int64_t len = arc_length_nm(r, chords.sweep_bam(), &radius_nm);
      piece(r.start, r.start, true, len);
      timed(r, true, len, radius_nm);
      PointNm from = r.start, to;
      while (chords.next(&to)) {
        piece(from, to, true, 0);
        from = to;
      }
      break;
    }
    case CanonKind::kDwell: {
      // The machine stops for a dwell (as for a tool change, a spindle
      // command, a pause and the end: LinuxCNC's queue waits for them).
      finish();
      const int64_t us = sat_mul_i64(r.dwell_ms, 1000);
      dwell_us_ = sat_add_i64(dwell_us_, us);
      if (move_sink_) move_sink_->move_time(MoveTimes{r.tool, kMoveDwell, us, us, us});
      break;
    }
    case CanonKind::kToolChange:
    case CanonKind::kSpindle:
    case CanonKind::kPause:
    case CanonKind::kEnd:
      finish();
      break;
    default:
      break;
  }
}

}  // namespace dexmill
