// The smiley of the paper's §3 and figure 12 (Table 2: 128 x 128 dexels, a
// 12-dexel ball), milled from the two-layer compound of equation 4: black
// above half the block's height, yellow below. The face is a disc raised in
// the black with a rounded edge; the eyes and the mouth are cut through the
// black, 2 mm into the yellow, so the milled part shows a yellow smile in
// black. At 0.5 mm a dexel the part is 64 mm square and the ball 6 mm
// across: the eyes (9 mm wide) and the mouth (9 mm) take it with room for
// a yellow floor beside its round bottom, the eyebrows (1 mm grooves) do
// not (the error view shows them left, §2.5). The pits are no deeper than
// they are wide (6.5 mm), so an oblique view still sees their floors.
#include <stdint.h>

#include "core/design/builtin_parts.h"
#include "core/design/builtin_shape.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

namespace {

constexpr int64_t kPitchNm = 500 * kNmPerUm;
constexpr int64_t kStockNm = 16 * kNmPerMm;  // the two-layer boundary at 8 mm

constexpr int64_t kFaceTopNm = 12500 * kNmPerUm;
constexpr int64_t kGroundNm = 9500 * kNmPerUm;   // around the face, still black
constexpr int64_t kCutFloorNm = 6 * kNmPerMm;    // eyes and mouth: 2 mm into the yellow
constexpr int64_t kBrowNm = 11500 * kNmPerUm;    // eyebrows: 1 mm grooves in the black

// The face: a disc of 28 mm with a quarter-round edge of 3 mm (face top
// down to the ground), centred on the part (dexel axes 0 .. 63.5 mm).
constexpr int64_t kCentreNm = 31750 * kNmPerUm;
constexpr int64_t kFaceRadiusNm = 28 * kNmPerMm, kEdgeRadiusNm = 3 * kNmPerMm;

// Eyes: upright ellipses 9 x 13 mm either side, above the centre.
constexpr int64_t kEyeDxNm = 9500 * kNmPerUm, kEyeDyNm = 8500 * kNmPerUm;
constexpr int64_t kEyeAxNm = 4500 * kNmPerUm, kEyeAyNm = 6500 * kNmPerUm;
// Eyebrows: arcs of 10 mm round each eye's centre, from 55 to 125 degrees.
constexpr int64_t kBrowRadiusNm = 10 * kNmPerMm, kBrowHalfWidthNm = 500 * kNmPerUm;
constexpr int32_t kBrowFromMdeg = 55000, kBrowToMdeg = 125000;
// Mouth: a band 9 mm wide along an arc of 15.5 mm round a point 3 mm
// above the centre, from 205 to 335 degrees (the lower part), ends round.
constexpr int64_t kMouthDyNm = 3 * kNmPerMm, kMouthRadiusNm = 15500 * kNmPerUm;
constexpr int64_t kMouthHalfWidthNm = 4500 * kNmPerUm;
constexpr int32_t kMouthFromMdeg = 205000, kMouthToMdeg = 335000;

int64_t smiley_height_nm(int64_t x_nm, int64_t y_nm) {
  const int64_t dx = x_nm - kCentreNm, dy = y_nm - kCentreNm;
  const int64_t r = hypot_round(dx, dy);
  if (r >= kFaceRadiusNm) return kGroundNm;
  if (arc_distance_nm(dx, dy - kMouthDyNm, kMouthRadiusNm, bam_from_mdeg(kMouthFromMdeg),
                      bam_from_mdeg(kMouthToMdeg)) < kMouthHalfWidthNm)
    return kCutFloorNm;
  constexpr int64_t kEyeSidesNm[] = {-kEyeDxNm, kEyeDxNm};
  for (int64_t side : kEyeSidesNm) {
    const int64_t ex = dx - side, ey = dy - kEyeDyNm;
    if (ellipse_q30(ex, ey, kEyeAxNm, kEyeAyNm) < kQ30One) return kCutFloorNm;
    if (arc_distance_nm(ex, ey, kBrowRadiusNm, bam_from_mdeg(kBrowFromMdeg), bam_from_mdeg(kBrowToMdeg)) <
        kBrowHalfWidthNm)
      return kBrowNm;
  }
  const int64_t edge_start = kFaceRadiusNm - kEdgeRadiusNm;
  if (r <= edge_start) return kFaceTopNm;
  return kGroundNm + round_profile_nm(r - edge_start, kEdgeRadiusNm);
}

}  // namespace

const BuiltinDesign kBuiltinSmiley = {
    "smiley", "the paper's smiley (figure 12): eyes and mouth cut through the black layer into the yellow",
    128, 128, kPitchNm, kStockNm, 12, "two-layer", smiley_height_nm, kCutFloorNm};

}  // namespace dexmill
