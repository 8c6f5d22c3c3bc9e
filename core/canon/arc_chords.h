// Splitting an arc or helix record (CanonKind::kArc) into chords whose
// sagitta is at most a given length: integer only, no heap, one point at a
// time. Used by `dexmill path`, and by the cutter to stamp or sweep arcs.
//
// The sweep follows LinuxCNC's ARC_FEED: from start around `centre` in the
// record's plane, counterclockwise for turns > 0, with |turns| - 1 extra full
// turns; start == end in the plane is a full circle. The radius goes
// linearly (by angle) from |start - centre| to |end - centre| (LinuxCNC's
// spiral for end points within tolerance), the plane's axis linearly from
// start to end (helix).
//
// Chord count: n = ceil(sweep / theta), theta = 2 acos(1 - s / r_max)
// (a few binary angles less, for CORDIC's error), at most a quarter turn,
// n <= 2^31 - 1. Error bound: every yielded point lies within
// 2 nm + 6e-9 * r of the exact curve (radius floored to 1 nm, output rounded
// to 1 nm, CORDIC sincos/atan2 of trig.h), the last point is the record's
// end exactly, and the chords' sagitta is <= s, so the polyline stays within
// s + 2 nm + 6e-9 * r of the arc (r = 1 m: s + 8 nm). tests/test_arc_chords.cpp
// checks this against a double-precision oracle.
#ifndef DEXMILL_CORE_CANON_ARC_CHORDS_H
#define DEXMILL_CORE_CANON_ARC_CHORDS_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/point.h"

namespace dexmill {

// The chords the cutter follows for the arcs it does not cut exactly
// (core/cut/sweep.h), and that the time estimate's boxes use: sagitta <= 1 um.
constexpr int64_t kArcChordSagittaNm = 1000;

class ArcChords {
 public:
  // Prepares the chords of `arc` (kind kArc) with sagitta <= max_sagitta_nm
  // (values below 1 nm count as 1 nm).
  void init(const CanonRecord& arc, int64_t max_sagitta_nm);
  // Number of chords (>= 1).
  uint32_t count() const { return n_; }
  // Signed sweep in binary angles (2^32 = one turn), > 0 counterclockwise.
  int64_t sweep_bam() const { return dir_ > 0 ? total_ : -total_; }
  // End point of the next chord; false after the last one.
  bool next(PointNm* p);
  // The point `along` binary angles from the start (0 <= along <= |sweep|),
  // with the radius and the axis coordinate interpolated as above.
  PointNm point_at(uint64_t along) const;
  // The larger of the start and end radii, nm.
  int64_t radius_max() const { return dr_ > 0 ? r0_ + dr_ : r0_; }
  Plane plane() const { return plane_; }

 private:
  Plane plane_;
  int64_t ca_, cb_;        // centre in the plane
  int64_t r0_, dr_;        // start radius, end radius - start radius
  int64_t c0_, dc_;        // axis coordinate at start, end - start
  uint32_t a0_;            // start angle
  int64_t total_;          // |sweep|, bam
  int dir_;                // +1 ccw, -1 cw
  uint32_t n_, k_;
  uint64_t step_q_, step_r_;  // total = step_q * n + step_r
  PointNm end_;
};

// Plane coordinates: (a, b) in the plane, c along its axis (see arc_center.h).
int64_t plane_a(Plane p, const PointNm& v);
int64_t plane_b(Plane p, const PointNm& v);
int64_t plane_c(Plane p, const PointNm& v);
PointNm plane_point(Plane p, int64_t a, int64_t b, int64_t c);

}  // namespace dexmill

#endif
