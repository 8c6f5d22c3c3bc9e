// The instrument panel of the paper's §3 (Table 2: 80 x 40 dexels, a
// 9-dexel ball), drawn here as a height field instead of the paper's scanned
// photograph: a raised rim, two round gauges (a dial recessed inside a
// raised ring, tick marks, a needle on a hub), three push buttons between
// them and "DEXMILL" engraved below. At 0.5 mm a dexel the part is 40 x 20
// mm and the ball 4.5 mm across: the rim, rings, dials and buttons are
// wider than the ball (their shapes come out), while the ticks, the needles
// and the one-dexel strokes of the lettering are finer than it (the error
// view shows them as material left, paper §2.5).
#include <stdint.h>

#include "core/design/builtin_font.h"
#include "core/design/builtin_parts.h"
#include "core/design/builtin_shape.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

namespace {

constexpr int64_t kPitchNm = 500 * kNmPerUm;

// Heights above the block's bottom.
constexpr int64_t kRimNm = 9 * kNmPerMm;
constexpr int64_t kRingNm = 8 * kNmPerMm;
constexpr int64_t kFaceNm = 7 * kNmPerMm;
constexpr int64_t kLetterNm = 6200 * kNmPerUm;  // engraved 0.8 mm into the face
constexpr int64_t kHubNm = 6500 * kNmPerUm;
constexpr int64_t kNeedleNm = 6 * kNmPerMm;
constexpr int64_t kTickNm = 5600 * kNmPerUm;
constexpr int64_t kDialNm = 5 * kNmPerMm;     // the panel's lowest face
constexpr int64_t kButtonNm = 1500 * kNmPerUm;  // a button's dome above the face

// The face inside the rim: the part's extent (dexel axes 0 .. 39.5 x 0 ..
// 19.5 mm) less 1.25 mm, corners rounded to 2.5 mm.
constexpr int64_t kFaceX0Nm = 1250 * kNmPerUm, kFaceX1Nm = 38250 * kNmPerUm;
constexpr int64_t kFaceY0Nm = 1250 * kNmPerUm, kFaceY1Nm = 18250 * kNmPerUm;
constexpr int64_t kFaceCornerNm = 2500 * kNmPerUm;

struct Gauge {
  int64_t cx_nm, cy_nm;
  int32_t needle_mdeg;  // where the needle points, from +x counterclockwise
};
constexpr Gauge kGauges[] = {{10 * kNmPerMm, 11750 * kNmPerUm, 150000}, {29500 * kNmPerUm, 11750 * kNmPerUm, 55000}};
constexpr int64_t kRingOuterNm = 6 * kNmPerMm, kDialRadiusNm = 4800 * kNmPerUm;
constexpr int64_t kHubRadiusNm = 900 * kNmPerUm;
constexpr int64_t kNeedleLengthNm = 4 * kNmPerMm, kNeedleHalfWidthNm = 350 * kNmPerUm;
// Nine ticks over 270 degrees, from 225 (lower left) clockwise to -45.
constexpr int32_t kTicks = 9;
constexpr int32_t kTickFirstMdeg = 225000, kTickStepMdeg = -33750;
constexpr int64_t kTickInnerNm = 3400 * kNmPerUm, kTickOuterNm = 4300 * kNmPerUm;
constexpr int64_t kTickHalfWidthNm = 250 * kNmPerUm;

// Three buttons stacked between the gauges, at the part's centre line.
constexpr int64_t kButtonXNm = 19750 * kNmPerUm, kButtonRadiusNm = 1500 * kNmPerUm;
constexpr int64_t kButtonYNm[] = {15250 * kNmPerUm, 11750 * kNmPerUm, 8250 * kNmPerUm};

// The lettering: one font pixel a dexel, its top-left pixel over dexel
// (19, 10), centred across the panel below the gauges.
constexpr const char* kText = "DEXMILL";
constexpr int32_t kTextI0 = 19, kTextJTop = 10;

// A radial stroke of the dial at `mdeg`, from r0 to r1 off the centre.
int64_t radial_distance_nm(int64_t dx_nm, int64_t dy_nm, int32_t mdeg, int64_t r0_nm, int64_t r1_nm) {
  const SinCosQ30 a = sincos_bam(bam_from_mdeg(mdeg));
  return segment_distance_nm(dx_nm, dy_nm, scale_nm(r0_nm, a.cos_q30), scale_nm(r0_nm, a.sin_q30),
                             scale_nm(r1_nm, a.cos_q30), scale_nm(r1_nm, a.sin_q30));
}

// The gauge's height at (dx, dy) from its centre, or -1 outside its ring.
int64_t gauge_nm(const Gauge& g, int64_t dx_nm, int64_t dy_nm) {
  const int64_t r = hypot_round(dx_nm, dy_nm);
  if (r > kRingOuterNm) return -1;
  if (r > kDialRadiusNm) return kRingNm;
  if (r <= kHubRadiusNm) return kHubNm;
  if (radial_distance_nm(dx_nm, dy_nm, g.needle_mdeg, 0, kNeedleLengthNm) <= kNeedleHalfWidthNm) return kNeedleNm;
  for (int32_t k = 0; k < kTicks; ++k)
    if (radial_distance_nm(dx_nm, dy_nm, kTickFirstMdeg + k * kTickStepMdeg, kTickInnerNm, kTickOuterNm) <=
        kTickHalfWidthNm)
      return kTickNm;
  return kDialNm;
}

int64_t panel_height_nm(int64_t x_nm, int64_t y_nm) {
  if (!in_rounded_rect(x_nm, y_nm, kFaceX0Nm, kFaceY0Nm, kFaceX1Nm, kFaceY1Nm, kFaceCornerNm)) return kRimNm;
  const int64_t col = div_round(x_nm, kPitchNm) - kTextI0, row = kTextJTop - div_round(y_nm, kPitchNm);
  if (text_ink(kText, static_cast<int32_t>(clamp<int64_t>(col, -1, 1000)), static_cast<int32_t>(clamp<int64_t>(row, -1, 1000))))
    return kLetterNm;
  for (const Gauge& g : kGauges) {
    const int64_t h = gauge_nm(g, x_nm - g.cx_nm, y_nm - g.cy_nm);
    if (h >= 0) return h;
  }
  for (int64_t by : kButtonYNm) {
    const int64_t dome = round_profile_nm(hypot_round(x_nm - kButtonXNm, y_nm - by), kButtonRadiusNm);
    if (dome > 0) return kFaceNm + muldiv_round(dome, kButtonNm, kButtonRadiusNm);
  }
  return kFaceNm;
}

}  // namespace

const BuiltinDesign kBuiltinPanel = {
    "panel", "the paper's instrument panel: rim, two gauges, buttons, engraved lettering",
    80, 40, kPitchNm, 10 * kNmPerMm, 9, "aluminium", panel_height_nm, kDialNm};

}  // namespace dexmill
