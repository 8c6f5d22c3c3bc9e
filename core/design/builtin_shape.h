// The integer shape kit the built-in design parts are drawn with
// (core/design/builtin.h): ellipses, smooth bumps, rounded profiles,
// distances to segments and arcs, periodic phases. Everything in nm in the
// design's own XY frame; fractions in q30. Each function states its error.
#ifndef DEXMILL_CORE_DESIGN_BUILTIN_SHAPE_H
#define DEXMILL_CORE_DESIGN_BUILTIN_SHAPE_H

#include <stdint.h>

namespace dexmill {

constexpr int64_t kQ30One = static_cast<int64_t>(1) << 30;

// (dx / ax)^2 + (dy / ay)^2 in q30: below kQ30One inside the ellipse with
// semi-axes ax, ay (> 0, < 2^30 nm), kQ30One on it. Saturates at 4.0 (a
// point that far out is outside every shape that asks). Error <= 1 q30 LSB.
int64_t ellipse_q30(int64_t dx_nm, int64_t dy_nm, int64_t ax_nm, int64_t ay_nm);

// (1 - u)^3 for u in [0, 1), 0 beyond, q30: a bump whose slope and
// curvature both fade to zero at its edge (u = 1), so sums of them are
// smooth. Error <= 2 q30 LSB.
int64_t bump_q30(int64_t u_q30);

// h * f, f in q30, rounded to nearest (ties up): error <= 0.5 nm.
// |h| < 2^32 nm, |f| <= 4.0.
int64_t scale_nm(int64_t h_nm, int64_t f_q30);

// sqrt(r^2 - s^2) for |s| < r, else 0: the height of a round (or, scaled,
// elliptic) profile of radius r at s from its crest. Error <= 0.5 nm.
// |s|, r < 2^31 nm.
int64_t round_profile_nm(int64_t s_nm, int64_t r_nm);

// Distance from p to the segment a-b (a point when a == b), nm, rounded.
// Error <= 1 nm. Coordinates within +-2^29 nm of each other.
int64_t segment_distance_nm(int64_t px_nm, int64_t py_nm, int64_t ax_nm, int64_t ay_nm, int64_t bx_nm,
                            int64_t by_nm);

// The phase of x in a wave of period `period_nm` (> 0) as a binary angle
// (2^32 a period; core/math/trig.h), rounded to nearest: error <= 0.5 bam.
// Any |x| < 2^62 nm.
uint32_t phase_bam(int64_t x_nm, int64_t period_nm);

// sin(phase) * a, rounded (sincos_bam's 2 q30 LSB plus the rounding: error
// <= 0.5 nm + 2e-9 |a|).
int64_t sine_nm(int64_t a_nm, uint32_t phase_bam);

// Distance from p (relative to the arc's centre) to the arc of radius r
// from angle a0 counterclockwise to a1 (binary angles): to the circle
// inside the arc's sector, else to the nearer end. Error <= 2 nm + the end
// points' CORDIC error (2e-9 r). |p|, r < 2^29 nm.
int64_t arc_distance_nm(int64_t dx_nm, int64_t dy_nm, int64_t r_nm, uint32_t a0_bam, uint32_t a1_bam);

// True when p lies in the rectangle [x0, x1] x [y0, y1] with corners
// rounded to radius r (exact).
bool in_rounded_rect(int64_t px_nm, int64_t py_nm, int64_t x0_nm, int64_t y0_nm, int64_t x1_nm, int64_t y1_nm,
                     int64_t r_nm);

}  // namespace dexmill

#endif
