// LinuxCNC's polar coordinates: the words @ (distance from the program
// origin) and ^ (angle from +X, counterclockwise, degrees) that stand for X
// and Y in the XY plane, as LinuxCNC 2.9 turns them into a point
// (interp_find.cc find_ends; interp_cycles.cc convert_cycle_xy and the
// repeats of CYCLE_MACRO). Everything is in the program frame: the caller
// removes the work and G92 offsets first and adds them back after.
//
// Integer only. Angles go to binary angles (2^32 a turn) through the
// expressions' bam_of_degrees (core/gcode/gvalue.h) and through CORDIC
// (core/math/trig.h: sincos_bam, atan2_bam); no second trigonometry.
//
// Error bound against exact arithmetic, for a result at distance rho from
// the origin (tests/test_polar.cpp checks it against a double oracle):
//   the angle:  ^ as written is exact in degrees e9; its binary angle is
//               rounded (0.5 bam = 7.3e-10 rad); a direction taken from the
//               current point (@ alone, G91) adds atan2_bam's 2 bam (2.9e-9
//               rad): at most 2.5 bam = 3.7e-9 rad in all;
//   sin, cos:   2 q30 units each, a vector error of 2.7e-9;
//   distances:  a distance taken from the current point is rounded to the
//               nearest nm (0.5 nm); the result to the nearest nm (0.71 nm).
//   In all: |error| <= 6.4e-9 * rho + 1.3 nm (rho = 10 m: 65 nm; 1 m: 8 nm).
#ifndef DEXMILL_CORE_INTERP_POLAR_H
#define DEXMILL_CORE_INTERP_POLAR_H

#include <stdint.h>

#include "core/gcode/error.h"

namespace dexmill {

struct PolarWords {
  bool has_radius;        // @
  bool has_angle;         // ^
  int64_t radius_nm;      // @ in nm (a length word in the program's units)
  int64_t angle_deg_e9;   // ^ in degrees e9 (any value; reduced modulo 360)
};

// A point's distance from the origin, rounded to the nearest nm.
int64_t polar_distance(int64_t x, int64_t y);

// G90 moves (find_ends): @ and ^ give the point; @ alone keeps the direction
// of (x, y), the current point; ^ alone keeps its distance. @ alone at the
// origin is kPolarNoAngle ('@' in *word). A negative @ goes the other way.
// For a canned cycle (cycle = true, convert_cycle_xy) @ alone at the origin
// takes the angle 0 instead.
GcodeError polar_absolute(int64_t x, int64_t y, const PolarWords& w, bool cycle, int64_t* px, int64_t* py,
                          char* word);

// G91 moves (find_ends): @ adds to the distance of (x, y) from the origin,
// then ^ to its angle (a distance that goes below zero comes out on the
// other side). From the origin either is kPolarIncrementalOrigin ('@' or
// '^' in *word); so is ^ after an @ that lands on the origin.
GcodeError polar_incremental(int64_t x, int64_t y, const PolarWords& w, int64_t* px, int64_t* py, char* word);

// The holes of a canned cycle repeated in G91 with @ and/or ^
// (CYCLE_MACRO): each repeat adds @ to the distance and ^ to the angle of the
// hole before (only when they are not zero). Hole k is computed from the
// first point and k, not from the hole before, so rounding does not pile up
// over the repeats: each hole has the error bound above.
class PolarSeries {
 public:
  void init(int64_t x, int64_t y, int64_t dr_nm, int64_t dangle_deg_e9);
  // The next hole into (*px, *py). False, with nothing set, when the hole
  // before is at the origin and a step needs its angle: LinuxCNC stops
  // there (kPolarIncrementalOrigin, '@' or '^' in *word).
  bool next(int64_t* px, int64_t* py, char* word);

 private:
  int64_t x0_, y0_;      // the first point
  int64_t rho_;          // distance of the hole before (>= 0)
  uint32_t angle0_bam_;  // direction of the first point
  uint32_t flip_bam_;    // half turns from distances that went below zero
  int64_t dr_;
  int64_t dangle_;       // ^ reduced to [0, 360) degrees e9
  int64_t k_;            // holes made
};

}  // namespace dexmill

#endif
