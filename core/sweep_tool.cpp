// Tool profiles in the sweep's working units (core/sweep.h).
#include "core/fixed.h"
#include "core/sweep.h"

namespace dexmill {

Status sweep_tool_prepare(const ToolProfile& p, int64_t lsb_nm, SweepTool* out) {
  constexpr int64_t kMaxRadiusNm = static_cast<int64_t>(1) << 28;
  if (lsb_nm < 1 || lsb_nm > (static_cast<int64_t>(1) << 30) || p.radius_nm < 1 || p.radius_nm > kMaxRadiusNm) return Status::kBadArgument;
  SweepTool t;
  t.kind = p.kind;
  t.r_u = p.radius_nm * kSweepUnitsPerNm;
  t.r2_u = t.r_u * t.r_u;
  t.rc_u = p.corner_nm * kSweepUnitsPerNm;
  t.a_u = t.r_u - t.rc_u;
  t.rc2_u = t.rc_u * t.rc_u;
  t.cot_q30 = p.kind == ToolKind::kVBit ? muldiv_round(p.cone_cos_q30, static_cast<int64_t>(1) << 30, p.cone_sin_q30) : 0;
  t.lsb_nm = lsb_nm;
  t.len_v = muldiv_round(p.length_nm, static_cast<int64_t>(1) << kSweepVBits, lsb_nm);
  // V per U = (lsb / 256) / (1/4 nm) inverted: 1 U = 256 / (4 * lsb) V.
  t.v_per_u_q32 = muldiv_round(static_cast<int64_t>(1) << (32 + kSweepVBits), 1, kSweepUnitsPerNm * lsb_nm);
  // ceil(2^62 / v_per_u_q32): lsb <= 2^30 nm (a grid's limit is 10^9), so
  // v_per_u_q32 >= 2^8 and the quotient is below 2^54.
  t.u_per_v_q30 = (static_cast<int64_t>(1) << 62) / t.v_per_u_q32 + 1;
  // floor(v_per_u_q32 * 2^24 / (2R)) < 2^39 * 2^24 / 8: no overflow.
  t.bowl_q56 = p.kind == ToolKind::kBall ? muldiv_floor(t.v_per_u_q32, static_cast<int64_t>(1) << 24, 2 * t.r_u) : 0;
  *out = t;
  return Status::kOk;
}

}  // namespace dexmill
