// The built-in designs' shape kit; see builtin_shape.h for the bounds.
#include "core/design/builtin_shape.h"

#include "core/math/fixed.h"
#include "core/math/trig.h"

namespace dexmill {

namespace {

constexpr int64_t kQ30Four = 4 * kQ30One;

// (d / a)^2 in q30, saturating at 4.0: |d| < 2a < 2^31 keeps d^2 exact.
int64_t ratio_sq_q30(int64_t d_nm, int64_t a_nm) {
  if (static_cast<int64_t>(abs_u64(d_nm) / 2) >= a_nm) return kQ30Four;
  return muldiv_round(d_nm * d_nm, kQ30One, a_nm * a_nm);
}

// a * b in q30, rounded to nearest (ties up); a, b in [0, 1].
int64_t mul_q30(int64_t a, int64_t b) { return (a * b + (kQ30One >> 1)) >> 30; }

}  // namespace

int64_t ellipse_q30(int64_t dx_nm, int64_t dy_nm, int64_t ax_nm, int64_t ay_nm) {
  return min_of(ratio_sq_q30(dx_nm, ax_nm) + ratio_sq_q30(dy_nm, ay_nm), kQ30Four);
}

int64_t bump_q30(int64_t u_q30) {
  if (u_q30 >= kQ30One) return 0;
  const int64_t v = kQ30One - max_of(u_q30, int64_t{0});
  return mul_q30(mul_q30(v, v), v);
}

int64_t scale_nm(int64_t h_nm, int64_t f_q30) { return (h_nm * f_q30 + (kQ30One >> 1)) >> 30; }

int64_t round_profile_nm(int64_t s_nm, int64_t r_nm) {
  if (static_cast<int64_t>(abs_u64(s_nm)) >= r_nm) return 0;
  return isqrt_round_u64(static_cast<uint64_t>(r_nm * r_nm - s_nm * s_nm));
}

int64_t segment_distance_nm(int64_t px_nm, int64_t py_nm, int64_t ax_nm, int64_t ay_nm, int64_t bx_nm,
                            int64_t by_nm) {
  const int64_t abx = bx_nm - ax_nm, aby = by_nm - ay_nm;
  const int64_t apx = px_nm - ax_nm, apy = py_nm - ay_nm;
  const int64_t dot = apx * abx + apy * aby, len2 = abx * abx + aby * aby;
  if (len2 == 0 || dot <= 0) return hypot_round(apx, apy);
  if (dot >= len2) return hypot_round(px_nm - bx_nm, py_nm - by_nm);
  // Inside the segment's span: |ap x ab| / |ab|, its square rounded once.
  const int64_t cross = apx * aby - apy * abx;
  return isqrt_round_u64(static_cast<uint64_t>(muldiv_round(cross, cross, len2)));
}

uint32_t phase_bam(int64_t x_nm, int64_t period_nm) {
  int64_t m = x_nm % period_nm;
  if (m < 0) m += period_nm;
  return static_cast<uint32_t>(static_cast<uint64_t>(muldiv_round(m, static_cast<int64_t>(1) << 32, period_nm)));
}

int64_t sine_nm(int64_t a_nm, uint32_t phase_bam) { return scale_nm(a_nm, sincos_bam(phase_bam).sin_q30); }

int64_t arc_distance_nm(int64_t dx_nm, int64_t dy_nm, int64_t r_nm, uint32_t a0_bam, uint32_t a1_bam) {
  if (static_cast<uint32_t>(atan2_bam(dy_nm, dx_nm) - a0_bam) <= static_cast<uint32_t>(a1_bam - a0_bam))
    return static_cast<int64_t>(abs_u64(static_cast<int64_t>(hypot_round(dx_nm, dy_nm)) - r_nm));
  const SinCosQ30 e0 = sincos_bam(a0_bam), e1 = sincos_bam(a1_bam);
  const int64_t d0 = hypot_round(dx_nm - scale_nm(r_nm, e0.cos_q30), dy_nm - scale_nm(r_nm, e0.sin_q30));
  const int64_t d1 = hypot_round(dx_nm - scale_nm(r_nm, e1.cos_q30), dy_nm - scale_nm(r_nm, e1.sin_q30));
  return min_of(d0, d1);
}

bool in_rounded_rect(int64_t px_nm, int64_t py_nm, int64_t x0_nm, int64_t y0_nm, int64_t x1_nm, int64_t y1_nm,
                     int64_t r_nm) {
  if (px_nm < x0_nm || px_nm > x1_nm || py_nm < y0_nm || py_nm > y1_nm) return false;
  const int64_t dx = px_nm - clamp(px_nm, x0_nm + r_nm, x1_nm - r_nm);
  const int64_t dy = py_nm - clamp(py_nm, y0_nm + r_nm, y1_nm - r_nm);
  return dx * dx + dy * dy <= r_nm * r_nm;
}

}  // namespace dexmill
