// Arc centres and checks; see arc_center.h for the rules and tolerances.
#include "core/interp/arc_center.h"

#include "core/math/fixed.h"
#include "core/math/wide.h"

namespace dexmill {

GcodeError arc_check_centre(const ArcPlanar& p, int64_t ca, int64_t cb, bool inch, int64_t* r1, int64_t* r2) {
  *r1 = hypot_floor(p.sa - ca, p.sb - cb);
  *r2 = hypot_floor(p.ea - ca, p.eb - cb);
  if (*r1 < kArcRadiusTolNm || *r2 < kArcRadiusTolNm) return GcodeError::kArcZeroRadius;
  const int64_t tol = inch ? kArcSpiralTolInchNm : kArcSpiralTolMmNm;
  const int64_t err = *r1 > *r2 ? *r1 - *r2 : *r2 - *r1;
  const int64_t rmax = *r1 > *r2 ? *r1 : *r2;
  // err * 1000 > rmax: the relative error is above 0.001 (no overflow: err < 2^37).
  if (err > 100 * tol || (err > tol && err * 1000 > rmax)) return GcodeError::kArcRadiusMismatch;
  return GcodeError::kOk;
}

GcodeError arc_centre_from_radius(const ArcPlanar& p, int64_t r_nm, bool cw, int64_t* ca, int64_t* cb,
                                  int64_t* a_nm, int64_t* b_nm) {
  const int64_t da = p.ea - p.sa, db = p.eb - p.sb;
  if (da == 0 && db == 0) return GcodeError::kArcRSameEnds;
  const int64_t r_abs = r_nm < 0 ? -r_nm : r_nm;
  // Chord length L and the centre's distance from the chord's midpoint,
  // h = sqrt(R^2 - L^2/4), both computed 2^24 times finer so that the
  // centre is right to well under a nanometre even for tiny chords.
  constexpr int kFine = 24;
  const U128 l2 = sum_sq_u128(da, db);
  const int64_t chord_nm = static_cast<int64_t>(isqrt_u128(l2));
  const int64_t half_nm = chord_nm / 2;
  if (half_nm - r_abs > kArcRadiusTolNm) {
    *a_nm = r_abs;
    *b_nm = half_nm;
    return GcodeError::kArcRTooSmall;
  }
  const U128 four_r2 = shl_u128(sq_u128(r_abs), 2);
  // 2h = sqrt(4R^2 - L^2), or 0 when R is within tolerance of half the chord.
  U128 disc{0, 0};
  if (u128_less(l2, four_r2)) disc = sub_u128(four_r2, l2);
  const int64_t two_h_fine = static_cast<int64_t>(isqrt_u128(shl_u128(disc, 2 * kFine)));
  const int64_t chord_fine = static_cast<int64_t>(isqrt_u128(shl_u128(l2, 2 * kFine)));
  // LinuxCNC: the centre is right of the chord (seen from start to end) for
  // G2 with R > 0 or G3 with R < 0, left otherwise.
  const bool right = cw == (r_nm > 0);
  // Unit normal to the chord, to the left: (-db, da) / L. Centre = mid + h * n.
  int64_t na = -db, nb = da;
  if (right) {
    na = db;
    nb = -da;
  }
  // h * n = na * (2h) / (2L): one rounding, exact 128-bit intermediate.
  const int64_t off_a = muldiv_round(na, two_h_fine, 2 * chord_fine);
  const int64_t off_b = muldiv_round(nb, two_h_fine, 2 * chord_fine);
  // Midpoint, rounded towards the start (ties are at half a nanometre).
  *ca = p.sa + div_floor(da, 2) + off_a;
  *cb = p.sb + div_floor(db, 2) + off_b;
  return GcodeError::kOk;
}

}  // namespace dexmill
