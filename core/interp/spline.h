// LinuxCNC's G5 (cubic spline) and G5.1 (quadratic B-spline) in the XY
// plane, as chords. LinuxCNC 2.9's interpreter hands NURBS_FEED the control
// points of one Bezier curve (interp_convert.cc convert_spline: G5.1 the
// start, start + (I, J) and the end; G5 the start, start + (I, J), end +
// (P, Q) and the end; its knot vector has no inner knots); its canonical
// output prints only NURBS_FEED(3 or 4, ...), the machine follows the curve
// by biarcs through 4 points per control point (emccanon.cc NURBS_FEED) and
// its preview draws 15 chords per control point (gcodemodule.cc). dexmill
// follows the curve itself, by chords of bounded sagitta.
//
// Chords: n of equal parameter step 1/n. A chord's distance from its piece
// of the curve is at most M / (8 n^2), M the largest |P''(u)| (for a
// polynomial curve, |P(u) - L(u)| <= (u - u0)(u1 - u) / 2 * M with L the
// chord), and |P''| is affine in u for a cubic, so M is its larger end
// value. n = ceil(sqrt(M / (8 s))) keeps that under the sagitta s. Points
// are computed exactly in 128-bit intermediates and rounded once: each
// within 1.1 nm of the curve (0.75 nm per coordinate); the first is the
// start, the last the end, exactly. So the polyline stays within s + 1.1 nm
// of the curve and the curve within s + 1.1 nm of the polyline
// (tests/test_spline.cpp checks both against a double oracle, and that the
// chords are not needlessly many).
//
// Range: control points within +-2e10 nm (the interpreter's 10 m positions
// plus handles of at most 10 m); then n <= 2^20 for s >= 1 nm and every
// intermediate fits int64.
#ifndef DEXMILL_CORE_INTERP_SPLINE_H
#define DEXMILL_CORE_INTERP_SPLINE_H

#include <stdint.h>

namespace dexmill {

// Sagitta of the interpreter's spline chords unless told otherwise (the
// cutter's arc chords are as fine: core/canon/arc_chords.h).
constexpr int64_t kSplineSagittaNm = 1000;
constexpr int64_t kSplineMaxControlNm = 20000000000;  // 20 m
constexpr uint32_t kSplineMaxChords = 1u << 20;

struct SplinePlan {
  uint8_t points;        // 3 (G5.1: quadratic) or 4 (G5: cubic)
  int64_t x[4], y[4];    // control points, nm; the last one (x[points-1]) is the end
  int64_t z_nm;          // the curve's height (splines do not move Z)
  uint32_t chords;       // n >= 1
  int64_t length_nm;     // sum of the chords' lengths (for G93), set by the interpreter
};

// n for sagitta <= sagitta_nm (values below 1 nm count as 1 nm).
uint32_t spline_chord_count(const SplinePlan& s, int64_t sagitta_nm);

// Chord point k of n (0 <= k <= n): the curve at u = k / n.
void spline_point(const SplinePlan& s, uint32_t k, int64_t* x, int64_t* y);

}  // namespace dexmill

#endif
