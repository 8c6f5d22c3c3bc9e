// Tool profiles in the sweep's working units (core/sweep.h).
#include "core/fixed.h"
#include "core/sweep.h"

namespace dexmill {

Status sweep_tool_prepare(const ToolProfile& p, int64_t lsb_nm, SweepTool* out) {
  constexpr int64_t kMaxRadiusNm = static_cast<int64_t>(1) << 28;
  if (lsb_nm < 1 || p.radius_nm < 1 || p.radius_nm > kMaxRadiusNm) return Status::kBadArgument;
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
  *out = t;
  return Status::kOk;
}

int64_t sweep_profile_v(const SweepTool& t, int64_t r2) {
  int64_t f_u = 0;
  switch (t.kind) {
    case ToolKind::kFlat:
      return 0;
    case ToolKind::kBall:  // R - sqrt(R^2 - r^2)
      f_u = t.r_u - static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(t.r2_u - r2)));
      break;
    case ToolKind::kBullNose: {  // flat to a, then the torus of radius rc
      const int64_t r = static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(r2)));
      if (r <= t.a_u) return 0;
      const int64_t d = min_of(r - t.a_u, t.rc_u);
      f_u = t.rc_u - static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(t.rc2_u - d * d)));
      break;
    }
    case ToolKind::kVBit:  // k * r
      f_u = mul_shift(static_cast<int64_t>(isqrt_fast_u64(static_cast<uint64_t>(r2))), t.cot_q30, 30);
      break;
  }
  return mul_shift(f_u, t.v_per_u_q32, 32);
}

}  // namespace dexmill
