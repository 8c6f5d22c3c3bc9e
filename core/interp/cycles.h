// Canned cycles G73, G74, G81-G89 with G98/G99 and L repeats, as LinuxCNC
// 2.9 runs them (interp_cycles.cc: convert_cycle_xy/yz/zx, CYCLE_MACRO and
// convert_cycle_gNN), in any of the three planes. Planning checks everything
// and cannot emit; emitting cannot fail, so a cycle block stays atomic.
#ifndef DEXMILL_CORE_INTERP_CYCLES_H
#define DEXMILL_CORE_INTERP_CYCLES_H

#include <stdint.h>

#include "core/canon/canon.h"
#include "core/interp/polar.h"
#include "core/point.h"

namespace dexmill {

// LinuxCNC's G83_RAPID_DELTA: 0.010 in, also 0.254 mm in G21.
constexpr int64_t kPeckBackoffNm = 254000;
// Pecks (G73, G83) one block may make, over all its repeats: a deep hole
// pecked finely needs thousands; millions mean Q is in the wrong units.
constexpr int64_t kMaxCyclePecks = 1000000;

struct CyclePlan {
  int16_t code;          // 730, 740, 810 ... 890
  Plane plane;
  int64_t a, b;          // first hole before adding the increment (plane coords, path frame)
  int64_t inc_a, inc_b;  // added before each repeat (G91), else 0
  int64_t repeats;       // L >= 1
  bool raise_first;      // below R: straight up to R first
  int64_t start_a, start_b;  // current position in the plane
  int64_t current_c;     // level of the first positioning move (after raising)
  int64_t r_c, bottom_c, clear_c;
  int64_t q_nm;          // peck (G73, G83)
  int64_t dwell_ms;      // G74, G82, G84, G86, G88, G89
  int32_t spindle_rpm;   // G74, G84, G86-G88: spindle at the outset, signed (M4 < 0), restored after each hole
  int64_t off_a, off_b;  // G87: offset out of the hole's axis (its I/J/K in the plane)
  int64_t middle_c;      // G87: top of the back bore
  // G91 with @ and ^ (XY only): the holes come from `series` (program
  // frame) plus (polar_off_a, polar_off_b) instead of the increments; the
  // last one is (last_a, last_b).
  bool polar;
  PolarSeries series;
  int64_t polar_off_a, polar_off_b;
  int64_t last_a, last_b;
};

// Receives what a cycle does: moves, dwells, spindle changes, a pause.
class CycleOut {
 public:
  virtual void move(CanonKind kind, const PointNm& to) = 0;
  virtual void dwell(int64_t ms) = 0;
  virtual void spindle(int32_t rpm) = 0;  // signed as CanonRecord::spindle_rpm; 0 = stopped
  virtual void pause() = 0;               // G88: the program stops for the operator

 protected:
  ~CycleOut() = default;
};

// Emits every move of the planned cycle, in LinuxCNC's order.
void cycle_emit(const CyclePlan& p, CycleOut* out);

// The last hole's position in the plane.
void cycle_last_hole(const CyclePlan& p, int64_t* a, int64_t* b);

// Where cycle_emit leaves the tool. LinuxCNC's interpreter then takes it to
// be at the clearance level over the last hole (its current position), and
// the next move starts from there in its reckoning; the tool is elsewhere
// after G88 (at the bottom: the operator was to retract it) and after
// G74/G84 in G18/G19 (see cycle_tap_point in cycles.cpp).
PointNm cycle_last_point(const CyclePlan& p);

// Number of pecks of G73/G83 from r down to bottom with increment q (q > 0).
int64_t cycle_peck_count(int64_t r_c, int64_t bottom_c, int64_t q_nm);

}  // namespace dexmill

#endif
