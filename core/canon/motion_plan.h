// A machine-aware time estimate: per-axis velocity and acceleration limits
// and corners blended within the path tolerance, the way LinuxCNC's
// trajectory planner runs a program (its "tangent" circular-arc blends of
// src/emc/tp, not the older parabolic ones). Integer only, no heap,
// streaming: a fixed ring of kPlanRing segments is the look-ahead.
//
// The model (what tests/test_motion_plan.cpp's double oracle computes too):
// - A segment is a straight move or a whole arc, at most its cruise velocity
//   (the feed, clamped; a rapid at the machine's rate), its direction's
//   per-axis limits (a path velocity or acceleration along unit u is
//   min over axes of limit_i / |u_i|), and an arc's normal acceleration
//   v^2 / r <= (sqrt(3)/2) a; on an arc the tangential acceleration is a / 2
//   (LinuxCNC's BLEND_ACC_RATIO_TANGENTIAL 0.5 and its normal share
//   sqrt(1 - 0.5^2)).
// - A junction ends the earlier segment by its path mode: G61 and G61.1 stop
//   there; G64 blends by a circular arc tangent to both segments, radius R
//   the largest with (a) the arc's deviation from the corner
//   R (1 / cos(phi / 2) - 1) <= P when G64 has P > 0 (phi: the turn angle),
//   (b) its tangent points at most half of each segment from the corner,
//   R tan(phi / 2) <= min(L1, L2) / 2; the corner velocity is then
//   sqrt((sqrt(3)/2) a_n R), a_n the per-axis acceleration limit along the
//   arc's normal (the corner's bisector), and at most both segments'
//   cruise velocities. Collinear segments (turn under 2^-30 rad) join at
//   the smaller cruise velocity. The blend's shortcut is not subtracted:
//   every segment keeps its whole length (an upper bound on the time of the
//   blend of at most 2 R tan(phi / 2) - R phi of path per corner).
// - Look-ahead: each junction's velocity is at most what the segments after
//   it, to the end of the ring, can decelerate to zero from; the program's
//   start, its end, dwells, tool changes, spindle commands and pauses stop.
// - Time: each segment a trapezoid between its junction velocities, v0 and
//   v1: L / vc + ((vc - v0)^2 + (vc - v1)^2) / (2 a vc) when it reaches its
//   cruise velocity vc, else (2 vp - v0 - v1) / a, vp^2 = a L + (v0^2 + v1^2) / 2.
//
// Integer bound: velocities are whole nm/s (square roots rounded down, so
// never above the model's), unit vectors Q30, blend radii in 2^-16 nm,
// times rounded to the us; a segment's time is within 3 us + 1e-6
// relative of the exact model's (the worst seen: 2.2 us beyond 1e-6) (tested against the
// double oracle over random sequences, corners, short segments and arcs).
#ifndef DEXMILL_CORE_CANON_MOTION_PLAN_H
#define DEXMILL_CORE_CANON_MOTION_PLAN_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/point.h"

namespace dexmill {

constexpr int kPlanRing = 48;  // segments of look-ahead (48 * 104-byte PlanSegment = 4992 bytes on x86-64)

// The machine: per axis (X, Y, Z) its velocity and acceleration limits; a
// path above max_path_nm_per_s is held to it (0: no such limit).
struct PlanLimits {
  int64_t velocity_nm_per_s[3] = {0, 0, 0};
  int64_t accel_nm_per_s2[3] = {0, 0, 0};
  int64_t max_path_nm_per_s = 0;
  // G64 with no P: this tolerance instead (0: none, as fast as possible).
  int64_t default_tolerance_nm = 0;
};

// What a finished segment carries back to its consumer.
struct PlanPayload {
  int32_t tool;
  uint8_t kind;  // the consumer's own class of the move
};

// A finished segment's three times under the machine's model, us: at its
// cruise velocity throughout (L / vc: no time to reach it), from rest to
// rest (the trapezoid between 0 and 0), and blended (between the junction
// velocities the look-ahead chose). cruise <= blended <= stop, always: the
// junction velocities lie in [0, vc] and the trapezoid's time falls as they rise.
struct PlanTimes {
  int64_t cruise_us, stop_us, blended_us;
};

struct PlanSegment {
  int64_t length_nm;
  int64_t cruise_nm_per_s;   // vc
  int64_t accel_nm_per_s2;   // tangential a
  int32_t dir_start[3], dir_end[3];  // unit tangents, Q30
  uint16_t path_mode;        // of the record: how the segment ends
  int64_t tolerance_nm;      // G64 P (0: none)
  int64_t junction_nm_per_s;  // at its start: the corner's limit
  int64_t entry_max_nm_per_s; // at its start: what the look-ahead allows
  PlanPayload payload;
};

class PlanSink {
 public:
  // One segment done: its times under the model.
  virtual void planned(const PlanPayload& p, const PlanTimes& t) = 0;

 protected:
  ~PlanSink() = default;
};

class MotionPlanner {
 public:
  void init(const PlanLimits& limits, PlanSink* sink);
  // A straight move from a to b (a rapid when feed_nm_per_min <= 0: then at
  // the axis-limited velocity); zero length: done at once with time 0.
  void line(const PointNm& a, const PointNm& b, int64_t feed_nm_per_min, const CanonRecord& r, const PlanPayload& p);
  // An arc of record r whose length and mean radius the caller measured.
  void arc(const CanonRecord& r, int64_t length_nm, int64_t radius_nm, const PlanPayload& p);
  // The machine stops here: every segment in the ring is done.
  void stop();
  int64_t total_us() const { return total_us_; }

  // The trapezoid of the model, us (v0, v1 <= vc; exposed for the tests).
  static int64_t segment_time_us(int64_t length_nm, int64_t v0, int64_t v1, int64_t vc, int64_t accel);
  // The velocity limit at the junction of a and then b (exposed for the tests).
  int64_t corner_limit(const PlanSegment& a, const PlanSegment& b) const;
  // The newest segment in the ring (count() > 0; for the tests).
  const PlanSegment& newest() const { return ring_[(head_ + count_ - 1) % kPlanRing]; }
  int count() const { return count_; }

 private:
  void push(PlanSegment s);
  void finish_oldest();

  PlanLimits lim_;
  PlanSink* sink_ = nullptr;
  PlanSegment ring_[kPlanRing];
  int head_ = 0, count_ = 0;
  int64_t v_start_nm_per_s_ = 0;  // the oldest segment's entry, fixed
  int64_t total_us_ = 0;
};

// Q30 unit vector of (x, y, z); false for the zero vector.
bool plan_unit_q30(int64_t x, int64_t y, int64_t z, int32_t out[3]);
// min over axes of limit_i * 2^30 / |u_i| (u Q30, limits > 0 only; axes
// with limit 0 do not limit); INT64_MAX when none does.
int64_t plan_axis_limited(const int64_t limit[3], const int32_t u[3]);

}  // namespace dexmill

#endif
