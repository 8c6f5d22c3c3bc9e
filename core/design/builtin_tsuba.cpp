// A tsuba (Japanese sword guard), the bronze workpiece of the paper's §3
// and figure 16 (no size in Table 2; ours: 192 x 192 dexels of 0.4 mm, an
// 8-dexel ball of 3.2 mm). A round plate of 72 mm with a half-round rim;
// the raised seppa-dai round the centre; the wedge-shaped nakago-ana (the
// tang's slot) and the two hitsu-ana either side (the kozuka's half-moon on
// the left, the kogai's, notched, on the right), recessed to a 2 mm floor
// (the part stays on its block); and a chrysanthemum in relief: eight domed
// petals, each with a vein down its middle, and a bead between each two.
// The petals, rim and holes are wider than the ball; the veins (0.6 mm)
// and the slot's narrow end are not (left in the error view, §2.5).
#include <stdint.h>

#include "core/design/builtin_parts.h"
#include "core/design/builtin_shape.h"
#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

namespace {

constexpr int64_t kPitchNm = 400 * kNmPerUm;
constexpr int64_t kCentreNm = 38200 * kNmPerUm;  // dexel axes 0 .. 76.4 mm

constexpr int64_t kFloorNm = 2 * kNmPerMm;       // around the plate and in the holes
constexpr int64_t kPlateNm = 5 * kNmPerMm;
constexpr int64_t kSeppaNm = 5600 * kNmPerUm;

// The rim: a half-round of 1.75 mm on the plate, from 32.5 to 36 mm out.
constexpr int64_t kPlateRadiusNm = 36 * kNmPerMm;
constexpr int64_t kRimMidNm = 34250 * kNmPerUm, kRimHalfNm = 1750 * kNmPerUm;

// The seppa-dai: an upright ellipse of 15 x 25 mm.
constexpr int64_t kSeppaAxNm = 7500 * kNmPerUm, kSeppaAyNm = 12500 * kNmPerUm;

// The nakago-ana: 12 mm tall from 6.5 mm below the centre, 2.6 mm wide at
// its foot widening to 4.2 mm, its top end round.
constexpr int64_t kSlotFootNm = -6500 * kNmPerUm, kSlotTopNm = 5500 * kNmPerUm;
constexpr int64_t kSlotFootHalfNm = 1300 * kNmPerUm, kSlotTopHalfNm = 2100 * kNmPerUm;

// The hitsu-ana: half-ellipses 4 x 12 mm, their flat sides 9.5 mm either
// side of the centre; the kogai's (right) keeps a round tongue of 1.2 mm
// in the middle of its flat side.
constexpr int64_t kHitsuFlatNm = 9500 * kNmPerUm, kHitsuAxNm = 4 * kNmPerMm, kHitsuAyNm = 6 * kNmPerMm;
constexpr int64_t kTongueRadiusNm = 1200 * kNmPerUm;

// The chrysanthemum: eight petals on axes at 22.5 + 45 k degrees, each an
// ellipse 14 mm long (centred 25 mm out) and 9 mm wide domed 1.5 mm above
// the plate, a vein 0.6 mm wide and 0.5 mm deep along its axis; beads of
// 1.3 mm radius at 29 mm out between them.
constexpr int64_t kFlowerInnerNm = 17 * kNmPerMm, kFlowerOuterNm = 32500 * kNmPerUm;
constexpr int64_t kPetalMidNm = 25 * kNmPerMm, kPetalAlongNm = 7 * kNmPerMm, kPetalAcrossNm = 4500 * kNmPerUm;
constexpr int64_t kPetalDomeNm = 1500 * kNmPerUm;
constexpr int64_t kVeinHalfNm = 300 * kNmPerUm, kVeinDepthNm = 500 * kNmPerUm;
constexpr int64_t kVeinFromNm = 19500 * kNmPerUm, kVeinToNm = 30 * kNmPerMm;
constexpr int64_t kBeadOutNm = 29 * kNmPerMm, kBeadRadiusNm = 1300 * kNmPerUm;
constexpr uint32_t kPetalSectorBam = 1u << 29;  // 45 degrees

bool in_slot(int64_t dx, int64_t dy) {
  if (hypot_round(dx, dy - kSlotTopNm) <= kSlotTopHalfNm) return true;
  if (dy < kSlotFootNm || dy > kSlotTopNm) return false;
  const int64_t half = kSlotFootHalfNm + muldiv_round(dy - kSlotFootNm, kSlotTopHalfNm - kSlotFootHalfNm,
                                                      kSlotTopNm - kSlotFootNm);
  return static_cast<int64_t>(abs_u64(dx)) <= half;
}

bool in_hitsu(int64_t dx, int64_t dy) {
  if (dx <= -kHitsuFlatNm) return ellipse_q30(dx + kHitsuFlatNm, dy, kHitsuAxNm, kHitsuAyNm) < kQ30One;
  if (dx >= kHitsuFlatNm)
    return ellipse_q30(dx - kHitsuFlatNm, dy, kHitsuAxNm, kHitsuAyNm) < kQ30One &&
           hypot_round(dx - kHitsuFlatNm, dy) > kTongueRadiusNm;
  return false;
}

// The flower's height over the plate at (dx, dy), r from the centre.
int64_t flower_nm(int64_t dx, int64_t dy) {
  const uint32_t angle = atan2_bam(dy, dx);
  // The petal whose 45-degree sector holds the point (petals are narrower
  // than their sectors, so no other one reaches it), in its own frame.
  const SinCosQ30 axis = sincos_bam((angle & ~(kPetalSectorBam - 1)) + kPetalSectorBam / 2);
  const int64_t along = scale_nm(dx, axis.cos_q30) + scale_nm(dy, axis.sin_q30);
  const int64_t across = scale_nm(dy, axis.cos_q30) - scale_nm(dx, axis.sin_q30);
  const int64_t u = ellipse_q30(along - kPetalMidNm, across, kPetalAlongNm, kPetalAcrossNm);
  if (u < kQ30One) {
    // An ellipsoid's dome: 1.5 mm sqrt(1 - u), sqrt in q30 to 1 LSB.
    int64_t h = scale_nm(kPetalDomeNm, isqrt_u64(static_cast<uint64_t>(kQ30One - u) << 30));
    if (static_cast<int64_t>(abs_u64(across)) <= kVeinHalfNm && along >= kVeinFromNm && along <= kVeinToNm)
      h -= kVeinDepthNm;
    return h;
  }
  // The bead on the sector boundary nearest the point.
  const SinCosQ30 b = sincos_bam((angle + kPetalSectorBam / 2) & ~(kPetalSectorBam - 1));
  return round_profile_nm(hypot_round(dx - scale_nm(kBeadOutNm, b.cos_q30), dy - scale_nm(kBeadOutNm, b.sin_q30)),
                          kBeadRadiusNm);
}

int64_t tsuba_height_nm(int64_t x_nm, int64_t y_nm) {
  const int64_t dx = x_nm - kCentreNm, dy = y_nm - kCentreNm;
  const int64_t r = hypot_round(dx, dy);
  if (r > kPlateRadiusNm) return kFloorNm;
  if (r >= kRimMidNm - kRimHalfNm) return kPlateNm + round_profile_nm(r - kRimMidNm, kRimHalfNm);
  if (in_slot(dx, dy) || in_hitsu(dx, dy)) return kFloorNm;
  if (ellipse_q30(dx, dy, kSeppaAxNm, kSeppaAyNm) < kQ30One) return kSeppaNm;
  if (r >= kFlowerInnerNm && r <= kFlowerOuterNm) return kPlateNm + flower_nm(dx, dy);
  return kPlateNm;
}

}  // namespace

const BuiltinDesign kBuiltinTsuba = {
    "tsuba", "a sword guard (figure 16): rim, tang slot, side holes, chrysanthemum relief",
    192, 192, kPitchNm, 8 * kNmPerMm, 8, "bronze", tsuba_height_nm, kFloorNm};

}  // namespace dexmill
