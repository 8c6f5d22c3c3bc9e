// The look-ahead planner of the machine-aware estimate; the model and its
// bounds: motion_plan.h.
#include "core/canon/motion_plan.h"

#include "core/canon/arc_chords.h"
#include "core/canon/summary.h"
#include "core/math/fixed.h"

namespace dexmill {

namespace {
constexpr int64_t kQ30 = int64_t{1} << 30;
// sqrt(3) / 2 rounded down: the normal share of the acceleration on arcs and
// blends (motion_plan.h), so a limit never exceeds the model's.
constexpr int64_t kNormalShareE9 = 866025403;
// |turn| under 4 * 2^-30 rad (the Q30 unit vectors' rounding) is collinear.
constexpr uint64_t kCollinearQ30 = 4;
// Velocities and accelerations no axis limits are held to 10^15 (a km/s,
// a km/s^2 in nm): beyond any machine, and their products stay in 128 bits.
constexpr int64_t kPlanMax = 1000000000000000LL;

U128 add_u128(U128 a, U128 b) {
  const uint64_t lo = a.lo + b.lo;
  return U128{a.hi + b.hi + (lo < a.lo ? 1u : 0u), lo};
}

U128 sq(int64_t v) { return mul_wide_u64(abs_u64(v), abs_u64(v)); }

// floor(sqrt(v0^2 + 2 a L)): the velocity after accelerating from v0 over L.
int64_t reach(int64_t v0, int64_t accel, int64_t length_nm) {
  const U128 s = add_u128(sq(v0), shl_u128(mul_wide_u64(static_cast<uint64_t>(accel), static_cast<uint64_t>(length_nm)), 1));
  return static_cast<int64_t>(isqrt_u128(s));
}

uint64_t norm_q30(const int64_t v[3]) {
  uint64_t s = 0;
  for (int i = 0; i < 3; ++i) s += static_cast<uint64_t>(v[i] * v[i]);  // |v_i| <= 2^31: fits
  return isqrt_u128(U128{0, s});
}
}  // namespace

bool plan_unit_q30(int64_t x, int64_t y, int64_t z, int32_t out[3]) {
  // Scaled up first so the norm's rounding (under 1 of >= 2^50) stays far
  // below the Q30 rounding even for a move of a few nm.
  const uint64_t big = max_of(abs_u64(x), max_of(abs_u64(y), abs_u64(z)));
  if (big == 0) return false;
  int shift = 0;
  while (shift < 62 && (big << shift) < (uint64_t{1} << 50)) ++shift;
  if (big >= (uint64_t{1} << 50)) shift = 0;
  const int64_t v[3] = {x * (int64_t{1} << shift), y * (int64_t{1} << shift), z * (int64_t{1} << shift)};
  const U128 s = add_u128(add_u128(sq(v[0]), sq(v[1])), sq(v[2]));
  const int64_t n = static_cast<int64_t>(isqrt_u128(s));
  for (int i = 0; i < 3; ++i) out[i] = static_cast<int32_t>(muldiv_round(v[i], kQ30, n));
  return true;
}

int64_t plan_axis_limited(const int64_t limit[3], const int32_t u[3]) {
  int64_t best = INT64_MAX;
  for (int i = 0; i < 3; ++i)
    if (limit[i] > 0 && u[i] != 0) best = min_of(best, muldiv_floor(limit[i], kQ30, static_cast<int64_t>(abs_u64(u[i]))));
  return best;
}

int64_t MotionPlanner::segment_time_us(int64_t length_nm, int64_t v0, int64_t v1, int64_t vc, int64_t accel) {
  if (vc <= 0 || length_nm <= 0) return 0;
  const U128 ends = add_u128(sq(v0), sq(v1));
  const U128 al = mul_wide_u64(static_cast<uint64_t>(accel), static_cast<uint64_t>(length_nm));
  const U128 need = shl_u128(sq(vc), 1);
  const U128 have = add_u128(shl_u128(al, 1), ends);
  if (have.hi > need.hi || (have.hi == need.hi && have.lo >= need.lo)) {
    // Cruise reached: L / vc plus what the ramps lose, (vc - v)^2 / (2 a vc) each.
    const int64_t lost = muldiv_round(vc - v0, vc - v0, vc) + muldiv_round(vc - v1, vc - v1, vc);
    return muldiv_round(length_nm, 1000000, vc) + muldiv_round(lost, 1000000, 2 * accel);
  }
  // A triangle to vp, vp^2 = a L + (v0^2 + v1^2) / 2.
  const U128 half_ends{ends.hi >> 1, (ends.lo >> 1) | (ends.hi << 63)};
  const int64_t vp = static_cast<int64_t>(isqrt_u128(add_u128(al, half_ends)));
  return muldiv_round(max_of<int64_t>(0, 2 * vp - v0 - v1), 1000000, accel);
}

void MotionPlanner::init(const PlanLimits& limits, PlanSink* sink) {
  lim_ = limits;
  sink_ = sink;
  head_ = count_ = 0;
  v_start_nm_per_s_ = 0;
  total_us_ = 0;
}

int64_t MotionPlanner::corner_limit(const PlanSegment& a, const PlanSegment& b) const {
  if (a.path_mode == 610 || a.path_mode == 611) return 0;  // G61, G61.1: exact stop
  const int64_t vmax = min_of(a.cruise_nm_per_s, b.cruise_nm_per_s);
  int64_t sum[3], diff[3];
  for (int i = 0; i < 3; ++i) {
    sum[i] = int64_t{a.dir_end[i]} + b.dir_start[i];
    diff[i] = int64_t{b.dir_start[i]} - a.dir_end[i];
  }
  // |diff| = 2 sin(phi / 2), |sum| = 2 cos(phi / 2), both Q30.
  const int64_t d = static_cast<int64_t>(norm_q30(diff)), c = static_cast<int64_t>(norm_q30(sum));
  if (d <= static_cast<int64_t>(kCollinearQ30)) return vmax;
  if (c == 0) return 0;  // a reversal
  // The radius in 2^-16 nm (a corner of short moves has one of a few nm).
  // (b): R tan(phi / 2) <= min(L1, L2) / 2.
  int64_t radius_q16 = muldiv_floor(min_of(a.length_nm, b.length_nm) / 2, c * 65536, d);
  const int64_t tol = a.tolerance_nm > 0 ? a.tolerance_nm : lim_.default_tolerance_nm;
  // (a): R (1 / cos - 1) <= P, that is R <= P cos (1 + cos) / sin^2 = P c (2 + c) / d^2.
  if (tol > 0) radius_q16 = min_of(radius_q16, muldiv_floor(muldiv_floor(tol * 65536, c, d), 2 * kQ30 + c, d));
  int32_t n[3];
  for (int i = 0; i < 3; ++i) n[i] = static_cast<int32_t>(muldiv_round(diff[i], kQ30, d));
  int64_t an = plan_axis_limited(lim_.accel_nm_per_s2, n);
  if (an == INT64_MAX) return vmax;
  an = muldiv_floor(an, kNormalShareE9, 1000000000);
  const int64_t v = static_cast<int64_t>(isqrt_u128(mul_wide_u64(static_cast<uint64_t>(an), static_cast<uint64_t>(radius_q16))) >> 8);
  return min_of(v, vmax);
}

void MotionPlanner::finish_oldest() {
  PlanSegment& o = ring_[head_];
  const int64_t exit_max = count_ > 1 ? ring_[(head_ + 1) % kPlanRing].entry_max_nm_per_s : 0;
  const int64_t v0 = v_start_nm_per_s_;
  const int64_t v1 = min_of(exit_max, reach(v0, o.accel_nm_per_s2, o.length_nm));
  const int64_t us = segment_time_us(o.length_nm, v0, v1, o.cruise_nm_per_s, o.accel_nm_per_s2);
  total_us_ = sat_add_i64(total_us_, us);
  if (sink_)
    sink_->planned(o.payload, PlanTimes{muldiv_round(o.length_nm, 1000000, o.cruise_nm_per_s),
                                        segment_time_us(o.length_nm, 0, 0, o.cruise_nm_per_s, o.accel_nm_per_s2), us});
  v_start_nm_per_s_ = v1;
  head_ = (head_ + 1) % kPlanRing;
  --count_;
}

void MotionPlanner::push(PlanSegment s) {
  s.cruise_nm_per_s = clamp<int64_t>(s.cruise_nm_per_s, 1, kPlanMax);
  s.accel_nm_per_s2 = clamp<int64_t>(s.accel_nm_per_s2, 1, kPlanMax);
  s.junction_nm_per_s = count_ > 0 ? corner_limit(ring_[(head_ + count_ - 1) % kPlanRing], s) : 0;
  if (count_ == 0) v_start_nm_per_s_ = 0;
  if (count_ == kPlanRing) finish_oldest();
  // Backward pass: the new segment ends at rest; earlier entries rise until
  // one is unchanged (each only grows as the ring grows, so the rest stay).
  s.entry_max_nm_per_s = min_of(s.junction_nm_per_s, reach(0, s.accel_nm_per_s2, s.length_nm));
  ring_[(head_ + count_) % kPlanRing] = s;
  ++count_;
  for (int k = count_ - 2; k >= 1; --k) {
    PlanSegment& g = ring_[(head_ + k) % kPlanRing];
    const int64_t exit_max = ring_[(head_ + k + 1) % kPlanRing].entry_max_nm_per_s;
    const int64_t e = min_of(g.junction_nm_per_s, reach(exit_max, g.accel_nm_per_s2, g.length_nm));
    if (e == g.entry_max_nm_per_s) break;
    g.entry_max_nm_per_s = e;
  }
}

void MotionPlanner::stop() {
  while (count_ > 0) finish_oldest();
  v_start_nm_per_s_ = 0;
}

void MotionPlanner::line(const PointNm& a, const PointNm& b, int64_t feed_nm_per_min, const CanonRecord& r,
                         const PlanPayload& p) {
  PlanSegment s{};
  s.length_nm = distance_nm(a, b);
  if (s.length_nm == 0 || !plan_unit_q30(b.x_nm - a.x_nm, b.y_nm - a.y_nm, b.z_nm - a.z_nm, s.dir_start)) {
    if (sink_) sink_->planned(p, PlanTimes{0, 0, 0});
    return;
  }
  for (int i = 0; i < 3; ++i) s.dir_end[i] = s.dir_start[i];
  int64_t vc = plan_axis_limited(lim_.velocity_nm_per_s, s.dir_start);
  if (feed_nm_per_min > 0) vc = min_of(vc, feed_nm_per_min / 60);
  if (lim_.max_path_nm_per_s > 0) vc = min_of(vc, lim_.max_path_nm_per_s);
  s.cruise_nm_per_s = vc;
  s.accel_nm_per_s2 = plan_axis_limited(lim_.accel_nm_per_s2, s.dir_start);
  s.path_mode = r.path_mode;
  s.tolerance_nm = r.path_tolerance_nm;
  s.payload = p;
  push(s);
}

namespace {
// The plane's axes (a, b, c) as X = 0, Y = 1, Z = 2 (arc_chords.h's plane_a..c).
void plane_axes(Plane pl, int out[3]) {
  out[0] = pl == Plane::kXY ? 0 : pl == Plane::kZX ? 2 : 1;
  out[1] = pl == Plane::kXY ? 1 : pl == Plane::kZX ? 0 : 2;
  out[2] = pl == Plane::kXY ? 2 : pl == Plane::kZX ? 1 : 0;
}

// min(limit_a, limit_b) * L / around and limit_c * L / |rise| (zero parts and
// zero limits do not limit).
int64_t arc_limited(const int64_t lim[3], const int ax[3], int64_t len, int64_t around, int64_t rise) {
  int64_t plane = INT64_MAX, best = INT64_MAX;
  if (lim[ax[0]] > 0) plane = lim[ax[0]];
  if (lim[ax[1]] > 0) plane = min_of(plane, lim[ax[1]]);
  if (plane != INT64_MAX && around > 0) best = muldiv_floor(plane, len, around);
  if (lim[ax[2]] > 0 && rise != 0) best = min_of(best, muldiv_floor(lim[ax[2]], len, static_cast<int64_t>(abs_u64(rise))));
  return best;
}
}  // namespace

void MotionPlanner::arc(const CanonRecord& r, int64_t length_nm, int64_t radius_nm, const PlanPayload& p) {
  const Plane pl = r.arc.plane;
  const int64_t rise = plane_c(pl, r.end) - plane_c(pl, r.start);
  const U128 l2 = sq(length_nm), r2 = sq(rise);
  const int64_t around = l2.hi > r2.hi || (l2.hi == r2.hi && l2.lo > r2.lo) ? static_cast<int64_t>(isqrt_u128(sub_u128(l2, r2))) : 0;
  if (length_nm <= 0 || around <= 0 || radius_nm <= 0) {
    line(r.start, r.end, r.feed_nm_per_min, r, p);
    return;
  }
  PlanSegment s{};
  s.length_nm = length_nm;
  // The tangent at a point with radius vector (ra, rb): rotation * (-rb, ra)
  // in the plane and the rise per radian times r / r along the axis.
  const int64_t sign = r.arc.turns < 0 ? -1 : 1, axial = muldiv_round(rise, radius_nm, around);
  const PointNm ends[2] = {r.start, r.end};
  int32_t* dirs[2] = {s.dir_start, s.dir_end};
  for (int k = 0; k < 2; ++k) {
    const int64_t ra = plane_a(pl, ends[k]) - plane_a(pl, r.arc.centre), rb = plane_b(pl, ends[k]) - plane_b(pl, r.arc.centre);
    const PointNm t = plane_point(pl, -sign * rb, sign * ra, axial);
    if (!plan_unit_q30(t.x_nm, t.y_nm, t.z_nm, dirs[k])) {
      line(r.start, r.end, r.feed_nm_per_min, r, p);
      return;
    }
  }
  int ax[3];
  plane_axes(pl, ax);
  int64_t vc = arc_limited(lim_.velocity_nm_per_s, ax, length_nm, around, rise);
  if (r.feed_nm_per_min > 0) vc = min_of(vc, r.feed_nm_per_min / 60);
  if (lim_.max_path_nm_per_s > 0) vc = min_of(vc, lim_.max_path_nm_per_s);
  // v^2 / r <= (sqrt(3)/2) a of the plane (a helix's larger effective radius ignored).
  const int64_t lim_ab[3] = {lim_.accel_nm_per_s2[ax[0]], lim_.accel_nm_per_s2[ax[1]], 0};
  const int ab[3] = {0, 1, 2};
  const int64_t a_plane = arc_limited(lim_ab, ab, around, around, 0);
  if (a_plane != INT64_MAX) {
    const int64_t an = muldiv_floor(a_plane, kNormalShareE9, 1000000000);
    vc = min_of(vc, static_cast<int64_t>(isqrt_u128(mul_wide_u64(static_cast<uint64_t>(an), static_cast<uint64_t>(radius_nm)))));
  }
  s.cruise_nm_per_s = vc;
  const int64_t at = arc_limited(lim_.accel_nm_per_s2, ax, length_nm, around, rise);
  s.accel_nm_per_s2 = at == INT64_MAX ? at : at / 2;  // the tangential half
  s.path_mode = r.path_mode;
  s.tolerance_nm = r.path_tolerance_nm;
  s.payload = p;
  push(s);
}

}  // namespace dexmill
