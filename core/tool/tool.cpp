// Tool profiles: the lower surface of each cutter shape, exact integer maths.
#include "core/tool/tool.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

Status tool_check(const Tool& t) {
  constexpr int64_t kMetre = 1000 * kNmPerMm;
  if (t.diameter_nm < kToolDiameterMinNm || t.diameter_nm > kToolDiameterMaxNm) return Status::kBadArgument;
  const int64_t r = t.diameter_nm / 2;
  switch (t.kind) {
    case ToolKind::kFlat:
    case ToolKind::kBall:
      break;
    case ToolKind::kBullNose:
      if (t.corner_radius_nm <= 0 || t.corner_radius_nm > r) return Status::kBadArgument;
      break;
    case ToolKind::kVBit:
      if (t.tip_angle_mdeg < kVBitAngleMinMdeg || t.tip_angle_mdeg > kVBitAngleMaxMdeg) return Status::kBadArgument;
      break;
    default:
      return Status::kBadArgument;
  }
  if (t.flutes < 0 || t.flutes > kToolFlutesMax) return Status::kBadArgument;
  if (t.length_nm > kToolLengthMaxNm || t.flute_length_nm < 0 || t.flute_length_nm > t.length_nm) return Status::kBadArgument;
  if (t.shank_diameter_nm < 0 || t.shank_diameter_nm > kMetre || t.holder_segments < 0 ||
      t.holder_segments > kHolderSegmentsMax)
    return Status::kBadArgument;
  int64_t holder_nm = 0;
  for (int k = 0; k < t.holder_segments; ++k) {
    const HolderSegment& h = t.holder[k];
    if (h.bottom_diameter_nm <= 0 || h.bottom_diameter_nm > kMetre || h.top_diameter_nm <= 0 ||
        h.top_diameter_nm > kMetre || h.height_nm <= 0 || h.height_nm > 10 * kMetre)
      return Status::kBadArgument;
    holder_nm += h.height_nm;
  }
  if (holder_nm > 10 * kMetre) return Status::kBadArgument;
  ToolProfile p = tool_profile(t);
  if (t.length_nm < profile_full_height_nm(p)) return Status::kBadArgument;
  return Status::kOk;
}

ToolProfile tool_profile(const Tool& t) {
  ToolProfile p;
  p.kind = t.kind;
  p.radius_nm = t.diameter_nm / 2;
  p.corner_nm = t.kind == ToolKind::kBullNose ? t.corner_radius_nm : 0;
  // Half the included angle, as a binary angle.
  SinCosQ30 sc = sincos_bam(bam_from_mdeg(t.tip_angle_mdeg / 2));
  p.cone_cos_q30 = sc.cos_q30;
  p.cone_sin_q30 = sc.sin_q30;
  p.length_nm = t.length_nm;
  return p;
}

int64_t profile_height_nm(const ToolProfile& p, int64_t r_nm) {
  const uint64_t r = abs_u64(r_nm);
  if (r > static_cast<uint64_t>(p.radius_nm)) return p.length_nm;
  return profile_height_r2_nm(p, r * r);
}

int64_t profile_height_r2_nm(const ToolProfile& p, uint64_t r2) {
  const uint64_t rad = static_cast<uint64_t>(p.radius_nm);
  if (r2 > rad * rad) return p.length_nm;
  switch (p.kind) {
    case ToolKind::kFlat:
      return 0;
    case ToolKind::kBall:  // R - sqrt(R^2 - r^2), one exact rounding
      return p.radius_nm - static_cast<int64_t>(isqrt_round_u64(rad * rad - r2));
    case ToolKind::kBullNose: {
      // rc - sqrt(rc^2 - (r - f)^2), f = R - rc, with r and the root in q16
      // (128-bit intermediates) so the steep edge of the torus stays exact.
      const uint64_t f = rad - static_cast<uint64_t>(p.corner_nm);
      const uint64_t r_q16 = isqrt_u128(shl_u128(U128{0, r2}, 32));
      const uint64_t f_q16 = f << 16;
      if (r_q16 <= f_q16) return 0;
      const uint64_t d_q16 = r_q16 - f_q16;
      const uint64_t rc = static_cast<uint64_t>(p.corner_nm);
      const U128 rc2 = shl_u128(mul_wide_u64(rc, rc), 32);
      const U128 d2 = mul_wide_u64(d_q16, d_q16);
      const bool past = d2.hi > rc2.hi || (d2.hi == rc2.hi && d2.lo >= rc2.lo);
      const uint64_t root_q16 = past ? 0 : isqrt_u128(sub_u128(rc2, d2));
      return div_round(static_cast<int64_t>((rc << 16) - root_q16), 65536);
    }
    case ToolKind::kVBit: {  // r / tan(a/2), r in q16
      const int64_t r_q16 = static_cast<int64_t>(isqrt_u128(shl_u128(U128{0, r2}, 32)));
      return div_round(muldiv_round(r_q16, p.cone_cos_q30, p.cone_sin_q30), 65536);
    }
  }
  return 0;
}

int64_t profile_full_height_nm(const ToolProfile& p) {
  switch (p.kind) {
    case ToolKind::kFlat: return 0;
    case ToolKind::kBall: return p.radius_nm;
    case ToolKind::kBullNose: return p.corner_nm;
    case ToolKind::kVBit: return muldiv_round(p.radius_nm, p.cone_cos_q30, p.cone_sin_q30);
  }
  return 0;
}

bool profile_explains_cut(const ToolProfile& p, const PointNm& tip, int64_t x_nm, int64_t y_nm, int64_t z_nm,
                          int64_t lsb_nm) {
  const int64_t dx = x_nm - tip.x_nm, dy = y_nm - tip.y_nm;
  const int64_t r = p.radius_nm;
  if (dx < -r || dx > r || dy < -r || dy > r) return false;
  const uint64_t r2 = static_cast<uint64_t>(dx * dx) + static_cast<uint64_t>(dy * dy);
  if (r2 > static_cast<uint64_t>(r) * static_cast<uint64_t>(r)) return false;
  return z_nm + lsb_nm >= tip.z_nm + profile_height_r2_nm(p, r2);
}

}  // namespace dexmill
