// Tool profiles in the sweep's working units (core/cut/sweep.h).
#include "core/cut/sweep.h"
#include "core/math/fixed.h"

namespace dexmill {

// Ranges (core/cut/sweep.h): R <= 2^28 nm, so r_u <= 2^30 and r2_u, rc2_u
// <= 2^60; the bull's q52 ratios <= 2^52 (their products shifted back);
// inv_r_q62 <= 2^62; a V-bit's cot_q30 < 2^37 (angles >= 1 degree,
// core/tool/tool.h); len_v < 2^42 (10 m over 1 nm LSBs, times 256);
// v_per_u_q32 in [2^8, 2^38], u_per_v_q30 < 2^54; the bowl's q < 2^32 by
// construction and r2 >> pre < 2^32. Every quotient by muldiv (128-bit).
Status sweep_tool_prepare(const ToolProfile& p, int64_t lsb_nm, SweepTool* out) {
  constexpr int64_t kMaxRadiusNm = static_cast<int64_t>(1) << 28;
  constexpr int64_t kMaxLsbNm = static_cast<int64_t>(1) << 30;
  if (lsb_nm < 1 || lsb_nm > kMaxLsbNm || p.radius_nm < 1 || p.radius_nm > kMaxRadiusNm) return Status::kBadArgument;
  SweepTool t;
  t.kind = p.kind;
  t.r_u = p.radius_nm * kSweepUnitsPerNm;
  t.r2_u = t.r_u * t.r_u;
  t.rc_u = p.corner_nm * kSweepUnitsPerNm;
  t.a_u = t.r_u - t.rc_u;
  t.rc2_u = t.rc_u * t.rc_u;
  // The bull nose's quartic (core/cut/bull_flank.h), once per tool.
  constexpr int64_t kQ52 = static_cast<int64_t>(1) << 52;
  t.bull_a_q52 = muldiv_round(t.a_u, kQ52, t.r_u);
  t.bull_rc_q52 = kQ52 - t.bull_a_q52;
  t.bull_rc2_q52 = mul_shift(t.bull_rc_q52, t.bull_rc_q52, 52);
  t.bull_2arc_q52 = 2 * mul_shift(t.bull_a_q52, t.bull_rc_q52, 52);
  t.bull_a2_q52 = mul_shift(t.bull_a_q52, t.bull_a_q52, 52);
  t.bull_inv_r_q62 = (static_cast<int64_t>(1) << 62) / t.r_u;
  t.cot_q30 = p.kind == ToolKind::kVBit ? muldiv_round(p.cone_cos_q30, static_cast<int64_t>(1) << 30, p.cone_sin_q30) : 0;
  t.lsb_nm = lsb_nm;
  t.len_v = muldiv_round(p.length_nm, static_cast<int64_t>(1) << kSweepVBits, lsb_nm);
  // V per U = (lsb / 256) / (1/4 nm) inverted: 1 U = 256 / (4 * lsb) V.
  t.v_per_u_q32 = muldiv_round(static_cast<int64_t>(1) << (32 + kSweepVBits), 1, kSweepUnitsPerNm * lsb_nm);
  // ceil(2^62 / v_per_u_q32): lsb <= 2^30 nm (a grid's limit is 10^9), so
  // v_per_u_q32 >= 2^8 and the quotient is below 2^54.
  t.u_per_v_q30 = (static_cast<int64_t>(1) << 62) / t.v_per_u_q32 + 1;
  // The bowl (sweep_bowl_v): r^2 >> pre below 2^32 for r^2 <= R^2, and
  // q = floor(g 2^(post + pre - 33) / R) (g = v_per_u_q32) with the largest
  // post <= 63 that keeps q below 2^32. Then (r^2 >> pre) q / 2^post <= r^2
  // g / (2^33 R), the paraboloid in V, and below it by at most 1 V (the last
  // floor), (r^2 >> pre) / 2^post for q's floor (2^-31 of the value when q
  // >= 2^31, else post = 63 and under 2^-31 V) and 2^pre U^2 of r^2 (2^pre
  // <= R^2 / 2^31): within 1 V + 2^-30 of its value at the rim, R g / 2^33.
  t.bowl_pre = 0;
  while ((static_cast<uint64_t>(t.r2_u) >> t.bowl_pre) >> 32) ++t.bowl_pre;
  t.bowl_q = 0;
  t.bowl_post = 0;
  for (int post = 63; post >= 0; --post) {
    const int e = post + t.bowl_pre - 33;  // in [-33, 58]: pre <= 28
    const int64_t q = e >= 0 ? muldiv_floor(t.v_per_u_q32, static_cast<int64_t>(1) << e, t.r_u)
                             : (t.v_per_u_q32 >> -e) / t.r_u;  // floor(floor(g / 2^-e) / R): still a floor
    if (q >= 0 && q < (static_cast<int64_t>(1) << 32)) {
      t.bowl_q = static_cast<uint32_t>(q);
      t.bowl_post = post;
      break;
    }
  }
  *out = t;
  return Status::kOk;
}

}  // namespace dexmill
