// The free-form surface of the paper's §3 and figures 14-15 (Table 2: 256 x
// 256 dexels, a 6-dexel ball), milled from white and blue marble: rolling
// hills made of two waves and three smooth bumps (a hill, a hollow, a
// peak). At 0.5 mm a dexel the part is 128 mm square and the ball 3 mm
// across. The surface is smooth enough for the ball to follow everywhere:
// the bumps lie apart (at most one under any point), so by the bounds below
// the slope stays under 0.34 + 0.29 + 0.35 < 1 (45 degrees) and the
// curvature under 0.056 + 0.033 + 0.060 = 0.15/mm, a radius above 6.5 mm,
// four times the ball's (tests measure both), and the error view shows
// only the scallops between zig rows.
#include <stdint.h>

#include "core/design/builtin_parts.h"
#include "core/design/builtin_shape.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

namespace {

constexpr int64_t kPitchNm = 500 * kNmPerUm;
constexpr int64_t kBaseNm = 17 * kNmPerMm;
constexpr int64_t kFloorNm = 4 * kNmPerMm;  // below the lowest point (about 6 mm)

// A product wave A sin(2 pi x / Lx + px) sin(2 pi y / Ly + py): slope <=
// 2 pi A sqrt(1/Lx^2 + 1/Ly^2) = 0.34, curvature <= 4 pi^2 A (1/Lx +
// 1/Ly)^2 = 0.056/mm.
constexpr int64_t kSwellNm = 4 * kNmPerMm;
constexpr int64_t kSwellLxNm = 96 * kNmPerMm, kSwellLyNm = 120 * kNmPerMm;
constexpr int64_t kSwellPxNm = 5 * kNmPerMm, kSwellPyNm = 17 * kNmPerMm;  // phases as shifts
// An oblique ripple A cos(2 pi (x - 0.6 y) / L): slope <= 2 pi A sqrt(1.36)
// / L = 0.29, curvature <= 4 pi^2 A 1.36 / L^2 = 0.033/mm.
constexpr int64_t kRippleNm = 2500 * kNmPerUm, kRippleLNm = 64 * kNmPerMm;

// Bumps h (1 - r^2/R^2)^3: slope <= 1.72 h / R, curvature <= 6 h / R^2.
struct Bump {
  int64_t cx_nm, cy_nm, r_nm, h_nm;
};
constexpr Bump kBumps[] = {
    {38 * kNmPerMm, 88 * kNmPerMm, 34 * kNmPerMm, 7 * kNmPerMm},    // the hill: slope 0.35, 0.036/mm
    {92 * kNmPerMm, 40 * kNmPerMm, 30 * kNmPerMm, -6 * kNmPerMm},   // the hollow: 0.34, 0.040/mm
    {100 * kNmPerMm, 102 * kNmPerMm, 20 * kNmPerMm, 4 * kNmPerMm},  // the peak: 0.34, 0.060/mm
};

int64_t freeform_height_nm(int64_t x_nm, int64_t y_nm) {
  int64_t h = kBaseNm;
  const int64_t sx = sincos_bam(phase_bam(x_nm + kSwellPxNm, kSwellLxNm)).sin_q30;
  const int64_t sy = sincos_bam(phase_bam(y_nm + kSwellPyNm, kSwellLyNm)).sin_q30;
  h += scale_nm(scale_nm(kSwellNm, sx), sy);
  h += scale_nm(kRippleNm, sincos_bam(phase_bam(x_nm - muldiv_round(y_nm, 3, 5), kRippleLNm)).cos_q30);
  for (const Bump& b : kBumps) h += scale_nm(b.h_nm, bump_q30(ellipse_q30(x_nm - b.cx_nm, y_nm - b.cy_nm, b.r_nm, b.r_nm)));
  return h;
}

}  // namespace

const BuiltinDesign kBuiltinFreeform = {
    "freeform", "the paper's free-form surface (figures 14-15): smooth hills and a hollow",
    256, 256, kPitchNm, 30 * kNmPerMm, 6, "marble", freeform_height_nm, kFloorNm};

}  // namespace dexmill
