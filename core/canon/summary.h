// What a program does, without cutting it: motion counted by kind, its
// bounding boxes, path lengths and an estimated machining time. A CanonSink,
// so one pass of the interpreter fills it (`dexmill run` does that pass
// first to size the default stock and to fill the report). Integer only, no
// heap: a controller can show the estimate before it starts.
//
// Time model (estimated_time_us): every straight move and every chord of an
// arc at its feed rate (the record's feed_nm_per_min; G93 gives the
// equivalent rate; at most max_feed_nm_per_min), every rapid at MotionTimeModel::rapid_nm_per_min,
// acceleration and corner slow-down ignored, dwells added, tool changes,
// spindle and coolant commands and pauses free. Arcs are measured by
// their true length: mean radius times the sweep, combined with the helix's
// rise (the boxes use the chords of sagitta <= kArcSagittaNm the cutter
// follows).
#ifndef DEXMILL_CORE_CANON_SUMMARY_H
#define DEXMILL_CORE_CANON_SUMMARY_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/canon/motion_plan.h"
#include "core/point.h"

namespace dexmill {

// A bounding box that grows point by point; empty until the first add.
struct BoxAccum {
  bool valid = false;
  PointNm lo{0, 0, 0}, hi{0, 0, 0};

  void add(const PointNm& p);
  void add(const BoxAccum& b);
};

struct MotionTimeModel {
  int64_t rapid_nm_per_min = 5000 * 1000000LL;  // 5000 mm/min
  // Feeds above this count at this rate: LinuxCNC takes any F and the
  // machine clamps it to its maximum velocity (the interpreter warns once).
  int64_t max_feed_nm_per_min = 1000000 * 1000000LL;  // 1e6 mm/min
  // > 0: every move (a straight move, or an arc as a whole) starts and ends
  // at rest and reaches its rate by this acceleration (a trapezoidal speed
  // profile, a triangle when the move is too short): an upper bound on
  // what a controller that blends moves takes. 0: no acceleration.
  int64_t accel_nm_per_s2 = 0;
  // The machine-aware estimate (core/canon/motion_plan.h) runs beside the
  // model above when blend is set and an acceleration is known: from
  // `axes` where any axis has one (a --machine; an axis without a
  // velocity takes rapid_nm_per_min, without an acceleration
  // accel_nm_per_s2), else every axis at rapid_nm_per_min and
  // accel_nm_per_s2 with the path held to rapid_nm_per_min.
  bool blend = false;
  PlanLimits axes;
};

// One move's (or dwell's) three times, to a MoveTimeSink: no acceleration,
// from rest to rest (the model's accel_nm_per_s2; without one, the same as
// no acceleration) and blended (without the planner, the model's figure).
struct MoveTimes {
  int32_t tool;   // the record's: in the spindle
  uint8_t kind;   // kMoveRapid, kMoveFeed, kMoveDwell
  int64_t no_accel_us, stop_us, blended_us;
};
constexpr uint8_t kMoveRapid = 0, kMoveFeed = 1, kMoveDwell = 2;

class MoveTimeSink {
 public:
  virtual void move_time(const MoveTimes& t) = 0;

 protected:
  ~MoveTimeSink() = default;
};

constexpr int kCanonKinds = 9;  // CanonKind values 0..8

class MotionSummary final : public CanonSink, private PlanSink {
 public:
  explicit MotionSummary(const MotionTimeModel& model = MotionTimeModel());

  void emit(const CanonRecord& r) override;
  // The program ended without M2/M30: the moves still in the look-ahead are
  // timed (the machine stops there). M2/M30 does this itself.
  void finish();
  // Each move's times, once the blended one is known (up to kPlanRing
  // moves later; no heap here, the sink sums them by tool).
  void set_move_sink(MoveTimeSink* s) { move_sink_ = s; }
  // The look-ahead's memory (about 5 KB), the caller's, before the first
  // record: only the pass that wants the blended figure pays for it (the
  // simulation's own clock, per move, is the model's). Without one, or
  // without the model's blend and an acceleration, blended = the model's.
  void set_planner(MotionPlanner* p);

  // Records by CanonKind (index static_cast<int>(kind)).
  uint64_t count(CanonKind k) const { return counts_[static_cast<int>(k)]; }
  // Every point the tool tip passes through (starts, ends, chord points).
  const BoxAccum& motion_box() const { return motion_; }
  // Points of feed moves and arcs (both ends of every straight piece).
  const BoxAccum& feed_box() const { return feed_; }
  // Points of the feed pieces that reach below z = 0 (both ends of each):
  // where a program with Z0 on the stock top cuts.
  const BoxAccum& feed_below_zero_box() const { return feed_below_zero_; }
  // The highest of the lower ends of the feed pieces: the highest level a
  // feed reaches and stays at or below (a plunge from a safe height counts
  // at its bottom). INT64_MIN without feeds.
  int64_t feed_level_top_nm() const { return feed_level_top_nm_; }
  int64_t feed_length_nm() const { return feed_nm_; }
  int64_t rapid_length_nm() const { return rapid_nm_; }
  int64_t estimated_time_us() const { return feed_us_ + rapid_us_ + dwell_us_; }
  int64_t feed_time_us() const { return feed_us_; }
  int64_t rapid_time_us() const { return rapid_us_; }
  int64_t dwell_time_us() const { return dwell_us_; }
  // The three estimates, dwells included: no acceleration, every move from
  // rest to rest, and blended (motion_plan.h; the model's own figure when
  // the planner does not run). The blended split into feeds and rapids.
  int64_t no_accel_time_us() const { return na_us_ + dwell_us_; }
  int64_t stop_time_us() const { return st_us_ + dwell_us_; }
  bool blending() const { return planning_; }
  int64_t blended_time_us() const { return planning_ ? bl_feed_us_ + bl_rapid_us_ + dwell_us_ : estimated_time_us(); }
  int64_t blended_feed_us() const { return planning_ ? bl_feed_us_ : feed_us_; }
  int64_t blended_rapid_us() const { return planning_ ? bl_rapid_us_ : rapid_us_; }

  // Time of one straight piece at a rate (nm/min), us, rounded; 0 for a
  // rate <= 0.
  static int64_t piece_time_us(int64_t length_nm, int64_t rate_nm_per_min);
  // Time of one move of the model: piece_time_us with the acceleration's
  // ramps, within 1.1 us of the exact trapezoid (tests/test_motion_summary.cpp).
  static int64_t move_time_us(const MotionTimeModel& m, int64_t length_nm, int64_t rate_nm_per_min);

 private:
  // One straight piece's boxes and length; len_nm < 0: its own length.
  void piece(const PointNm& a, const PointNm& b, bool feed, int64_t len_nm);
  // One move's times: the model's, and the planner's once it is done.
  void timed(const CanonRecord& r, bool feed, int64_t len_nm, int64_t radius_nm);
  void planned(const PlanPayload& p, const PlanTimes& t) override;

  MotionTimeModel model_;
  uint64_t counts_[kCanonKinds] = {};
  BoxAccum motion_, feed_, feed_below_zero_;
  int64_t feed_level_top_nm_ = INT64_MIN;
  int64_t feed_nm_ = 0, rapid_nm_ = 0;
  int64_t feed_us_ = 0, rapid_us_ = 0, dwell_us_ = 0;
  int64_t na_us_ = 0, st_us_ = 0, bl_feed_us_ = 0, bl_rapid_us_ = 0;
  bool planning_ = false, want_plan_ = false;
  PlanLimits limits_;
  MotionPlanner* plan_ = nullptr;
  MoveTimeSink* move_sink_ = nullptr;
};

// |b - a| in nm, rounded down (exact 128-bit sum of squares).
int64_t distance_nm(const PointNm& a, const PointNm& b);
// An arc's true length for its sweep (ArcChords::sweep_bam): the mean
// radius (*radius_nm) times the sweep, with the helix's rise.
int64_t arc_length_nm(const CanonRecord& r, int64_t sweep_bam, int64_t* radius_nm);

}  // namespace dexmill

#endif
