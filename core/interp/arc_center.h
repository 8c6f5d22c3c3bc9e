// Arc centres and LinuxCNC's arc checks (interp_arc.cc: arc_data_ijk and
// arc_data_r, with the default tolerances of interp_internal.hh), in the two
// in-plane coordinates (a, b) = (X, Y) for G17, (Z, X) for G18, (Y, Z) for
// G19; counterclockwise turns from +a towards +b.
//
// Centre format (I/J/K): both radii must be at least RADIUS_TOLERANCE
// (0.00005 in = 1270 nm, mm and inch alike), and with e = |r_end - r_start|
// the arc is refused when e > 100 * T, or when e > T and e / max(r) > 0.001,
// where T = CENTER_ARC_RADIUS_TOLERANCE: 2 * 0.01 * sqrt(2) mm (28284 nm) in
// G21, 2 * 0.001 * sqrt(2) in (71842 nm) in G20. (LinuxCNC 2.9 as shipped in
// Debian 12 behaves so; a tolerated difference becomes a spiral.)
// Radius format (R): refused when start == end, or when half the chord
// exceeds |R| by more than RADIUS_TOLERANCE; R < 0 asks for the long way.
#ifndef DEXMILL_CORE_INTERP_ARC_CENTER_H
#define DEXMILL_CORE_INTERP_ARC_CENTER_H

#include <stdint.h>

#include "core/gcode/error.h"

namespace dexmill {

constexpr int64_t kArcRadiusTolNm = 1270;
constexpr int64_t kArcSpiralTolMmNm = 28284;
constexpr int64_t kArcSpiralTolInchNm = 71842;

struct ArcPlanar {
  int64_t sa, sb;  // start
  int64_t ea, eb;  // end
};

// Centre format: checks the given centre (ca, cb). On error sets *r1, *r2
// to the two radii (for the message).
[[nodiscard]] GcodeError arc_check_centre(const ArcPlanar& p, int64_t ca, int64_t cb, bool inch, int64_t* r1,
                                          int64_t* r2);

// Radius format: finds the centre for signed radius r_nm (clockwise if cw).
// On error sets *a_nm = |R| and *b_nm = half the chord.
[[nodiscard]] GcodeError arc_centre_from_radius(const ArcPlanar& p, int64_t r_nm, bool cw, int64_t* ca, int64_t* cb,
                                                int64_t* a_nm, int64_t* b_nm);

}  // namespace dexmill

#endif
